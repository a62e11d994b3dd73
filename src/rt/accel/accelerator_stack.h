// The intersection method a run uses, as a stack of layers over the method the settings name:
// the debugging layers next to it (-ds strike check, -dl log), exit-ray culling around those
// (unless -De), and z-buffer first hits on top (--zbuffer). The program fills the settings from
// its switches; the stack knows nothing of switches or consoles.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
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

struct AcceleratorStackSettings {
    AccelSettings method;             ///< which method, and how (header, --accel, -o switches)
    bool exit_culling = true;         ///< false with -De
    bool check_exit_culling = false;  ///< -de: re-trace every culled ray
    bool zbuffer_first_hits = false;  ///< --zbuffer
    bool strike_check = false;        ///< -ds
    bool strike_print = false;        ///< -dsp: print each difference (implies the check)
    bool strike_voxels = false;       ///< -dso: ... with the voxels walked (implies it too)
    bool log_intersections = false;   ///< -dl
    bool trace_fill = false;          ///< -dof: method.fill_trace gets `trace`
    std::optional<std::filesystem::path> octree_listing;  ///< -doo: write the octree there
    TextSink note;     ///< a debugging switch with nothing to act on
    TextSink warning;  ///< a layer that had to turn itself off
    /// -dsp, -dso, -dl and -dof lines; called from the rendering threads, one call at a time.
    TextSink trace;
};

class AcceleratorStack {
public:
    /// Builds every layer; the scene must outlive the stack. Throws as make_accelerator does, and
    /// IoError when the octree listing cannot be written.
    AcceleratorStack(const Scene& scene, const AcceleratorStackSettings& settings);
    const Accelerator& top() const { return *top_; }
    /// What -p (and -de) print about the layers above the method.
    std::vector<std::string> report_lines() const;
    /// -ds: what the strike check found, when it ran.
    const StrikeCheck* strike_check() const { return strike_; }

private:
    std::unique_ptr<Accelerator> base_;  ///< the method, its debugging layers, exit culling
    const StrikeCheck* strike_ = nullptr;
    const ExitCulling* culling_ = nullptr;
    std::unique_ptr<ZBufferFirstHits> zbuffer_;
    const Accelerator* top_ = nullptr;
};

}  // namespace rt
