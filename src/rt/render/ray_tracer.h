// The ray tree (manual 1.3): a ray finds its first polygon, takes the local illumination there,
// and spawns a mirror-reflected and a refracted ray down to the header's maxdepth.
#pragma once

#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/core/rgb.h"
#include "rt/scene/scene.h"
#include "rt/shading/illumination.h"
#include "rt/shading/lights.h"
#include "rt/shading/shading_settings.h"

namespace rt {

class RayTracer {
public:
    /// shadow_feeling: the header's lghtick (0 none, 1 vertices, 2 centres), before -Ds.
    RayTracer(const Scene& scene, const Accelerator& accel, const ShadingSettings& settings);

    /// Intensity arriving along the ray (unit direction) from its origin's side; depth 1 is the
    /// eye ray. Light picked up at distance d is attenuated by the -A formula unless -Da.
    Rgb trace(const Ray& ray, int depth, TraceCounters& counters) const;

    /// Distance under which a hit counts as the surface a ray leaves from.
    double epsilon() const { return epsilon_; }
    const std::vector<PointLight>& lights() const { return lights_; }

private:
    Rgb secondary_rays(const Ray& ray, const SurfacePoint& s, int depth,
                       TraceCounters& counters) const;
    Rgb refracted_rays(const Ray& ray, const SurfacePoint& s, int depth,
                       TraceCounters& counters) const;

    const Scene& scene_;
    const Accelerator& accel_;
    ShadingSettings settings_;
    std::vector<PointLight> lights_;
    double epsilon_ = 1e-9;
    int max_depth_ = 1;
};

}  // namespace rt
