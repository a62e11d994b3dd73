// The intersection method a run uses, as a stack: the method the scene header or --accel names,
// wrapped in exit-ray culling (unless -De), with z-buffer first hits on top (--zbuffer).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"
#include "rt/accel/debug/strike_check.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/accel/zbuffer/zbuffer_first_hits.h"
#include "rt/app/options.h"
#include "rt/app/run.h"
#include "rt/scene/scene.h"

namespace rt {

/// The header's method (0 0 brute force, 1 depth octree, N 0 SEADS) unless --accel names
/// another; -od overrides the octree depth; the -o switches fill the rest.
AccelSettings accel_settings(const Scene& scene, const Options& options);

class AcceleratorStack {
public:
    /// Builds every layer; the scene must outlive the stack.
    AcceleratorStack(const Scene& scene, const Options& options, const RunConsole& console);
    const Accelerator& top() const { return *top_; }
    /// What -p (and -de) print about the layers above the method.
    std::vector<std::string> report_lines() const;
    /// -ds: what the strike check found, when it ran.
    const StrikeCheck* strike_check() const { return strike_; }

private:
    std::unique_ptr<Accelerator> base_;  ///< the method, or exit culling around it
    const StrikeCheck* strike_ = nullptr;
    const ExitCulling* culling_ = nullptr;
    std::unique_ptr<ZBufferFirstHits> zbuffer_;
    const Accelerator* top_ = nullptr;
};

}  // namespace rt
