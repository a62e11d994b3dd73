// Intel Embree 3 as an intersection method, for comparison only (the lab and --accel embree).
// Embree intersects in single precision and is not watertight against our exact test, so it may
// name a different polygon, or none, for rays through edges and corners, and its t is a float's.
// Built only when CMake finds Embree 3 (RT_WITH_EMBREE), and linked: loaded on demand like SDL2
// and Assimp, its TBB threads crashed LeakSanitizer's exit check (docs/accelerators.md).
#pragma once

#include <memory>

#include "rt/accel/accelerator.h"

namespace rt {

/// The scene must outlive the result. Polygons are cut into fans of triangles; a hit on any of
/// them reports its polygon. `build_threads` threads build it (0: Embree's default, every core).
/// Throws Error if Embree cannot make a device.
std::unique_ptr<Accelerator> make_embree_accelerator(const Scene& scene,
                                                     unsigned build_threads = 0);

}  // namespace rt
