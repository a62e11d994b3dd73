// The ray tree (manual 1.3): a ray finds its first polygon, takes the local illumination there,
// and spawns reflected and refracted rays (and, without shadow feelers, diffuse rays) down to the
// header's maxdepth. Down to maxdist they are distributed in their cones by the cos^n law, as
// many as the adaptive rule (-Xr) asks for; deeper, or with -Dd, one ray each.
#pragma once

#include <cstdint>
#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/core/rgb.h"
#include "rt/render/ray_kinds.h"
#include "rt/sampling/directions.h"
#include "rt/sampling/sample_stream.h"
#include "rt/sampling/strata.h"
#include "rt/scene/scene.h"
#include "rt/shading/illumination.h"
#include "rt/shading/lights.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// What one sample's ray tree did, for -dx.
struct RayTreeCounts {
    std::uint32_t distributed_intersections = 0;  ///< hits that distributed rays
    std::uint32_t distributed_rays = 0;           ///< rays they sent
};

/// The state of one sample being traced: its random numbers and counters.
struct SampleContext {
    SampleStream& stream;
    KindCounters& counters;
    RayTreeCounts& tree;
    std::int64_t last_polygon = -1;  ///< the polygon the last traced ray met, -1 for none
};

class RayTracer {
public:
    RayTracer(const Scene& scene, const Accelerator& accel, const ShadingSettings& settings);

    /// Intensity arriving along the ray (unit direction) from its origin's side; depth 1 is the
    /// eye ray. Light picked up at distance d is attenuated by the -A formula unless -Da.
    /// `distributed`: the ray is one of a distribution, or descends from one (without -I it gets
    /// the simple model).
    Rgb trace(const Ray& ray, RayKind kind, int depth, bool distributed,
              SampleContext& sample) const;

    /// The polygon a ray meets first (-1 for none), without shading it.
    std::int64_t first_polygon(const Ray& ray, TraceCounters& counters) const;

private:
    struct Lobe;
    Rgb secondary_rays(const Ray& ray, const SurfacePoint& s, int depth, bool full,
                       SampleContext& sample) const;
    Rgb refracted_rays(const Ray& ray, const SurfacePoint& s, int depth, bool distribute,
                       bool simple, SampleContext& sample) const;
    /// The mean intensity over a lobe: one ray along its axis, or a distribution of rays.
    /// `simple`: the rays descend from a distributed ray and keep its simple model (no -I).
    Rgb gather(const Lobe& lobe, const SurfacePoint& s, int depth, bool distribute, bool simple,
               SampleContext& sample) const;

    const Scene& scene_;
    const Accelerator& accel_;
    ShadingSettings settings_;
    std::vector<PointLight> lights_;
    ProgressiveStrata ray_strata_;  ///< the strata of distributed rays at one intersection
    double epsilon_ = 1e-9;
    int max_depth_ = 1;
    double max_distributed_depth_ = 0.0;  ///< the header's maxdist
    bool diffuse_rays_ = false;           ///< no shadow feelers: light arrives by diffuse rays
};

}  // namespace rt
