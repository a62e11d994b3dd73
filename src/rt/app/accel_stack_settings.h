// The intersection method's settings as the scene header and the switches give them: the stack
// itself (rt/accel/accelerator_stack.h) knows nothing of switches or consoles.
#pragma once

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator_stack.h"
#include "rt/app/options.h"
#include "rt/app/run.h"
#include "rt/scene/scene.h"

namespace rt {

/// The header's method (0 0 brute force, 1 depth octree, N 0 SEADS) unless --accel names
/// another; -od overrides the octree depth; the -o switches fill the rest.
AccelSettings accel_settings(const Scene& scene, const Options& options);

/// The whole stack: the method, -De, -de, --zbuffer and the debugging switches (-ds, -dsp, -dso,
/// -dl, -doo writing octree.lst in the current folder, -dof), their messages to the console.
AcceleratorStackSettings accelerator_stack_settings(const Scene& scene, const Options& options,
                                                    const RunConsole& console);

}  // namespace rt
