#include "rt/render/ray_tracer.h"

#include <algorithm>

#include "rt/shading/optics.h"
#include "rt/shading/surface_point.h"

namespace rt {

namespace {

// Hits closer than this fraction of the scene's size to a ray's origin are the surface the ray
// leaves from, not a new surface.
constexpr double kRelativeEpsilon = 1e-9;

double scene_epsilon(const Scene& scene) {
    Vec3 lo;
    Vec3 hi;
    scene.bounds(lo, hi);
    return kRelativeEpsilon * std::max(1.0, length(hi - lo));
}

}  // namespace

RayTracer::RayTracer(const Scene& scene, const Accelerator& accel,
                     const ShadingSettings& settings)
    : scene_(scene),
      accel_(accel),
      settings_(settings),
      epsilon_(scene_epsilon(scene)),
      max_depth_(scene.header.maxdepth) {
    if (settings_.shadow_feelers) {
        lights_ = collect_point_lights(scene, scene.header.lghtick);
    }
}

Rgb RayTracer::trace(const Ray& ray, int depth, TraceCounters& counters) const {
    ++counters.rays;
    const std::optional<Hit> hit = accel_.closest_hit(ray, {epsilon_, 1e300}, counters);
    if (!hit) {
        return {};  // the background is black
    }
    ++counters.hits;
    const SurfacePoint s = describe_hit(scene_, settings_, ray, *hit);
    const IlluminationContext context{scene_, accel_, settings_, lights_, epsilon_};
    Rgb result = local_illumination(context, s, -ray.direction, counters);
    if (depth < max_depth_) {
        result += secondary_rays(ray, s, depth, counters);
    }
    if (settings_.attenuate_rays) {
        result *= settings_.attenuation(hit->t);
    }
    return result;
}

Rgb RayTracer::secondary_rays(const Ray& ray, const SurfacePoint& s, int depth,
                              TraceCounters& counters) const {
    Rgb result;
    const Attribute& a = *s.attribute;
    if (settings_.reflection && a.specular > 0.0) {
        Vec3 mirrored = reflect(ray.direction, s.shading_normal);
        if (dot(mirrored, s.facing_normal) <= 0.0) {
            mirrored = reflect(ray.direction, s.facing_normal);  // smoothing bent it inside
        }
        result += trace({s.position, normalize(mirrored)}, depth + 1, counters) * a.specular;
    }
    if (s.transmission > 0.0) {
        result += refracted_rays(ray, s, depth, counters) * a.color * s.transmission;
    }
    return result;
}

// One refracted ray, or with -R and differing indices one per colour channel, each keeping only
// its own channel. Total internal reflection sends the ray back inside.
Rgb RayTracer::refracted_rays(const Ray& ray, const SurfacePoint& s, int depth,
                              TraceCounters& counters) const {
    const Rgb& index = s.attribute->refraction_index;
    const bool split = index.r != index.g || index.g != index.b;
    Rgb result;
    for (int channel = 0; channel < (split ? 3 : 1); ++channel) {
        const double n = index[channel];
        const double n1 = s.front ? 1.0 : n;
        const double n2 = s.front ? n : 1.0;
        const std::optional<Vec3> bent = refract(ray.direction, s.shading_normal, n1, n2);
        Vec3 direction = bent ? normalize(*bent) : reflect(ray.direction, s.shading_normal);
        const bool goes_through = dot(direction, s.facing_normal) < 0.0;
        if (bent && !goes_through) {
            direction = ray.direction;  // smoothing tilted it back out: go straight through
        }
        const Rgb traced = trace({s.position, direction}, depth + 1, counters);
        if (!split) {
            return traced;
        }
        result[channel] = traced[channel];
    }
    return result;
}

}  // namespace rt
