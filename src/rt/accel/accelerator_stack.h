// The intersection method a run uses, as a stack of layers over the method the settings name:
// the debugging layers next to it (-ds strike check, -dl log), exit-ray culling around those
// (unless -De), and z-buffer first hits on top (--zbuffer). The program fills the settings from
// its switches; the stack knows nothing of switches or consoles.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"
#include "rt/accel/debug/strike_check.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/accel/zbuffer/zbuffer_first_hits.h"
#include "rt/scene/scene.h"

namespace rt {

/// Where a layer's messages go, one line each, without a newline; may be empty (then dropped).
using TextSink = std::function<void(const std::string&)>;

/// Where the layers' messages go.
struct AccelMessages {
    TextSink note;     ///< a debugging switch with nothing to act on
    TextSink warning;  ///< a layer that had to turn itself off
    /// -dsp, -dso, -dl and -dof lines; called from the rendering threads, one call at a time.
    TextSink trace;
};

/// Why exit culling, though not switched off, is left out of this scene's stack (its table
/// cannot pay for itself: settings.most_eye_rays); empty when it is built or switched off.
std::string exit_culling_left_out(const Scene& scene, const AcceleratorStackSettings& settings);

class AcceleratorStack {
public:
    /// Builds every layer; the scene must outlive the stack. Throws as make_accelerator does, and
    /// IoError when the octree listing cannot be written.
    AcceleratorStack(const Scene& scene, const AcceleratorStackSettings& settings,
                     const AccelMessages& messages);
    const Accelerator& top() const { return *top_; }
    /// What -p (and -de) print about the layers above the method.
    std::vector<std::string> report_lines() const;
    /// -ds: what the strike check found, when it ran.
    const StrikeCheck* strike_check() const { return strike_; }

private:
    std::unique_ptr<Accelerator> base_;  ///< the method, its debugging layers, exit culling
    const StrikeCheck* strike_ = nullptr;
    const ExitCulling* culling_ = nullptr;
    /// Why exit culling was left out though not switched off (-p says it); empty otherwise.
    std::string culling_left_out_;
    std::unique_ptr<ZBufferFirstHits> zbuffer_;
    const Accelerator* top_ = nullptr;
};

}  // namespace rt
