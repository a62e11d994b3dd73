// The intersection-method debugging switches, applied around the method the run built: -doo
// writes octree.lst, -ds/-dsp/-dso wrap it in the strike check, -dl in the intersection log.
#pragma once

#include <memory>

#include "rt/accel/accelerator.h"
#include "rt/accel/debug/strike_check.h"
#include "rt/app/options.h"
#include "rt/app/run.h"

namespace rt {

struct DebuggedAccelerator {
    std::unique_ptr<Accelerator> accel;
    const StrikeCheck* strike = nullptr;  ///< inside `accel`, when -ds, -dsp or -dso was given
};

/// Writes octree.lst (in the current folder) for -doo, then wraps `accel` as the switches say.
/// Reports go to console.trace.
DebuggedAccelerator add_accel_debugging(const Scene& scene, std::unique_ptr<Accelerator> accel,
                                        const Options& options, const RunConsole& console);

}  // namespace rt
