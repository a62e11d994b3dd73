// An upper bound on the rays one pixel sample can send: where maxdepth and surfaces that both
// reflect and transmit make the ray tree double (or worse) at every level, a render can take
// longer than anyone will wait, and the user should hear so before it starts.
#pragma once

#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

struct RayTreeBound {
    /// Rays one eye ray can spawn down to maxdepth, itself and shadow feelers included (a
    /// double: the bound can exceed every integer type).
    double rays_per_sample = 1.0;
    /// The most secondary rays one hit can send, over the scene's surfaces (its first level).
    double widest_branching = 0.0;
};

/// Above this many rays per sample a warning is given: a million rays is already seconds per
/// pixel, and the bound grows by the branching factor with every level of maxdepth.
inline constexpr double kExplodingRayTree = 1e6;

/// The bound for the scene's surfaces, header (maxdepth, maxdist, lghtick, sample resolution)
/// and the shading settings, with no weight cutoff: every hit is assumed to be of the surface
/// that sends the most rays, and the adaptive rule to ask for every ray.
RayTreeBound ray_tree_bound(const Scene& scene, const ShadingSettings& settings);

}  // namespace rt
