#include "rt/render/ray_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "rt/sampling/adaptive_mean.h"
#include "rt/sampling/sampling_settings.h"
#include "rt/shading/optics.h"
#include "rt/shading/surface_point.h"

namespace rt {

namespace {

// Hits closer than this fraction of the scene's size to a ray's origin are the surface the ray
// leaves from, not a new surface.
constexpr double kRelativeEpsilon = 1e-9;

double scene_epsilon(const Scene& scene) {
    return kRelativeEpsilon * std::max(1.0, length(scene.bounds().extent()));
}

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

// A distributed direction that fell on the wrong side of the surface is mirrored back across it,
// so the lobe keeps its energy instead of losing the part cut off by the surface.
Vec3 keep_on_side(const Vec3& direction, const Vec3& side_normal, bool same_side) {
    const double along = dot(direction, side_normal);
    if ((same_side && along > 0.0) || (!same_side && along < 0.0)) {
        return direction;
    }
    return normalize(direction - side_normal * (2.0 * along));
}

}  // namespace

/// Where the rays of one lobe go: around `axis`, within `cone`, on the `outside` of the surface
/// (the side the ray came from) or through it; `diffuse` lobes are cosine-weighted hemispheres.
struct RayTracer::Lobe {
    Vec3 axis;
    CosPowerCone cone;
    bool outside = true;
    bool diffuse = false;
    RayKind kind = RayKind::Reflected;
    const ConeShape* shape = nullptr;  ///< the cone's shape, worked out once; null: from `cone`
};

const RayTracer::MaterialCones* RayTracer::cones_of(const SurfacePoint& s) const {
    const std::uint32_t index = s.polygon < scene_.polygons.size()
                                    ? scene_.polygons[s.polygon].attribute
                                    : std::uint32_t{0xffffffffu};
    return index < cones_.size() && &scene_.attributes[index] == s.attribute ? &cones_[index]
                                                                             : nullptr;
}

RayTracer::RayTracer(const Scene& scene, const Accelerator& accel, const ShadingSettings& settings)
    : scene_(scene),
      accel_(accel),
      settings_(settings),
      ray_strata_(scene.view.sample_resolution_x, scene.view.sample_resolution_y),
      epsilon_(scene_epsilon(scene)),
      max_depth_(scene.header.maxdepth),
      max_distributed_depth_(scene.header.maxdist) {
    if (settings_.shadow_feelers) {
        lights_ =
            collect_point_lights(scene, scene.header.lghtick, settings_.share_light_among_points);
    }
    cones_.reserve(scene.attributes.size());
    for (const Attribute& a : scene.attributes) {
        cones_.push_back({ConeShape({radians(a.reflect_cone_degrees), a.reflect_cone_exponent}),
                          ConeShape({radians(a.refract_cone_degrees), a.refract_cone_exponent})});
    }
    diffuse_rays_ = !settings_.shadow_feelers || scene.header.lghtick == 0;
    // Only a packet walk makes feelers cheaper asked eight at a time; a method that asks the
    // lanes one by one would pay for the planning and gain nothing.
    feelers_ahead_ = !lights_.empty() && !settings_.fuzzy.enabled() && accel.walks_packets();
}

std::optional<Hit> RayTracer::nearest_hit(const Ray& ray, RayStart start,
                                          TraceCounters& counters) const {
    const Interval t{epsilon_, kBeyondAnyScene};
    return start == RayStart::Eye ? accel_.eye_ray_closest_hit(ray, t, counters)
                                  : accel_.closest_hit(ray, t, counters);
}

Rgb RayTracer::trace(const Ray& ray, RayKind kind, int depth, bool distributed,
                     SampleContext& sample, double weight) const {
    if (stop_ != nullptr && stop_->load(std::memory_order_relaxed)) {
        return {};  // abandoned: the caller discards the sample
    }
    TraceCounters& counters = sample.counters[kind];
    ++counters.rays;
    const std::optional<Hit> hit =
        nearest_hit(ray, kind == RayKind::Eye ? RayStart::Eye : RayStart::Elsewhere, counters);
    return shade(ray, hit, kind, depth, distributed, sample, weight);
}

void RayTracer::eye_ray_hits(std::span<const Ray> rays, std::span<std::optional<Hit>> hits,
                             TraceCounters& counters) const {
    if (stop_ != nullptr && stop_->load(std::memory_order_relaxed)) {
        return;  // abandoned: trace_eye_ray returns black without looking at the hits
    }
    RayPacket packet;
    packet.t.fill(Interval{epsilon_, kBeyondAnyScene});
    PacketHits found;
    for (std::size_t first = 0; first < rays.size(); first += kPacketSize) {
        const std::size_t lanes = std::min<std::size_t>(kPacketSize, rays.size() - first);
        std::copy_n(rays.begin() + static_cast<std::ptrdiff_t>(first), lanes, packet.rays.begin());
        packet.active = (1u << lanes) - 1u;
        accel_.eye_ray_closest_hit_packet(packet, found, counters);
        std::copy_n(found.begin(), lanes, hits.begin() + static_cast<std::ptrdiff_t>(first));
    }
}

Rgb RayTracer::trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit,
                             SampleContext& sample) const {
    return trace_found(ray, hit, RayKind::Eye, 1, false, sample, 1.0);
}

Rgb RayTracer::trace_found(const Ray& ray, const std::optional<Hit>& hit, RayKind kind, int depth,
                           bool distributed, SampleContext& sample, double weight) const {
    if (stop_ != nullptr && stop_->load(std::memory_order_relaxed)) {
        return {};  // abandoned: the caller discards the sample
    }
    ++sample.counters[kind].rays;
    return shade(ray, hit, kind, depth, distributed, sample, weight);
}

Rgb RayTracer::shade(const Ray& ray, const std::optional<Hit>& hit, RayKind kind, int depth,
                     bool distributed, SampleContext& sample, double weight) const {
    TraceCounters& counters = sample.counters[kind];
    if (!hit) {
        sample.last_seen = {};
        return {};  // the background is black
    }
    ++counters.hits;
    const SurfacePoint s = describe_hit(scene_, settings_, ray, *hit);
    // Without -I a distributed ray's hit gets the simple model: no highlights and no further
    // distribution (manual Appendix -I: "the distributed rays are not given the full
    // illumination model treatment").
    const bool full = !distributed || settings_.sampling.illuminate_distributed;
    // The eye ray's own hit may have its feelers planned and asked already (eye_feelers).
    const IlluminationContext context{
        scene_,
        accel_,
        settings_,
        lights_,
        epsilon_,
        &sample.stream,
        kind == RayKind::Eye && depth == 1 ? sample.eye_feelers : std::span<const FeelerAnswer>{}};
    TraceCounters& feelers = sample.counters[RayKind::ShadowFeeler];
    const std::uint64_t stops_before = feelers.hits;  // a feeler's hit is a polygon on its way
    Rgb result = local_illumination(context, s, -ray.direction, full, feelers);
    const SurfaceSeen seen{hit->polygon, feelers.hits - stops_before};
    if (depth < max_depth_) {
        result += secondary_rays(ray, s, depth, full, sample, weight);
    }
    if (settings_.attenuate_rays) {
        result *= settings_.attenuation(hit->t);
    }
    sample.last_seen = seen;  // after the subtree, which overwrote it
    return result;
}

SurfaceSeen RayTracer::first_surface(const Ray& ray, RayStart start, bool full,
                                     SampleContext& sample) const {
    TraceCounters& counters = sample.counters[RayKind::Probe];
    ++counters.rays;
    const std::optional<Hit> hit = nearest_hit(ray, start, counters);
    if (!hit) {
        return {};
    }
    ++counters.hits;
    const SurfacePoint s = describe_hit(scene_, settings_, ray, *hit);
    const IlluminationContext context{scene_, accel_, settings_, lights_, epsilon_, &sample.stream};
    TraceCounters& feelers = sample.counters[RayKind::ShadowFeeler];
    const std::uint64_t stops_before = feelers.hits;
    local_illumination(context, s, -ray.direction, full, feelers);  // for its feelers only
    return {hit->polygon, feelers.hits - stops_before};
}

// Each branch carries its weight, the coefficients along its path multiplied (for colours, their
// largest channel); with --cutoff a branch lighter than the threshold is not traced (adaptive
// tree-depth control, Hall and Greenberg 1983).
Rgb RayTracer::secondary_rays(const Ray& ray, const SurfacePoint& s, int depth, bool full,
                              SampleContext& sample, double weight) const {
    const Attribute& a = *s.attribute;
    const bool distribute =
        full && settings_.sampling.distribute && depth <= max_distributed_depth_;
    const LobeRays rays = distribute ? LobeRays::Distributed
                          : full     ? LobeRays::Axis
                                     : LobeRays::AxisSimple;
    bool distributed_here = false;
    Rgb result;
    const double colour_weight = std::max({s.color.r, s.color.g, s.color.b});
    const double reflected_weight = weight * a.specular;
    if (settings_.reflection && a.specular > 0.0 && worth_tracing(reflected_weight)) {
        Vec3 mirrored = reflect(ray.direction, s.shading_normal);
        if (settings_.correct_smoothing && dot(mirrored, s.facing_normal) <= 0.0) {
            mirrored = reflect(ray.direction, s.facing_normal);  // smoothing bent it inside
        }
        const MaterialCones* cones = cones_of(s);
        const Lobe lobe{normalize(mirrored),
                        {radians(a.reflect_cone_degrees), a.reflect_cone_exponent},
                        true,
                        false,
                        RayKind::Reflected,
                        cones != nullptr ? &cones->reflect : nullptr};
        distributed_here = distributed_here || (distribute && lobe.cone.half_angle > 0.0);
        result += gather(lobe, s, depth, rays, sample, reflected_weight) * a.specular;
    }
    const double transmitted_weight = weight * s.transmission * colour_weight;
    if (s.transmission > 0.0 && worth_tracing(transmitted_weight)) {
        distributed_here = distributed_here || (distribute && a.refract_cone_degrees > 0.0);
        result += refracted_rays(ray, s, depth, rays, sample, transmitted_weight) * s.color *
                  s.transmission;
    }
    const double diffuse_weight = weight * a.diffuse * colour_weight;
    if (diffuse_rays_ && a.diffuse > 0.0 && worth_tracing(diffuse_weight)) {
        // Without shadow feelers light reaches a point only along rays that find emitters
        // (manual Appendix -Ds); diffuse reflection then needs rays of its own.
        const Lobe lobe{s.shading_normal, {}, true, true, RayKind::Diffuse};
        distributed_here = distributed_here || distribute;
        result += gather(lobe, s, depth, rays, sample, diffuse_weight) * s.color * a.diffuse;
    }
    if (distributed_here) {
        ++sample.tree.distributed_intersections;
    }
    return result;
}

// One refracted ray, or with -R and differing indices one per colour channel, each keeping only
// its own channel. Total internal reflection sends the ray back inside.
Rgb RayTracer::refracted_rays(const Ray& ray, const SurfacePoint& s, int depth, LobeRays rays,
                              SampleContext& sample, double weight) const {
    const Attribute& a = *s.attribute;
    const Rgb& index = a.refraction_index;
    const MaterialCones* cones = cones_of(s);
    const bool split = index.r != index.g || index.g != index.b;
    Rgb result;
    for (int channel = 0; channel < (split ? 3 : 1); ++channel) {
        const double n = index[channel];
        const double n1 = s.front ? 1.0 : n;
        const double n2 = s.front ? n : 1.0;
        const std::optional<Vec3> bent = refract(ray.direction, s.shading_normal, n1, n2);
        Vec3 direction = bent ? normalize(*bent) : reflect(ray.direction, s.shading_normal);
        const bool goes_through = dot(direction, s.facing_normal) < 0.0;
        if (settings_.correct_smoothing && bent && !goes_through) {
            direction = ray.direction;  // smoothing tilted it back out: go straight through
        }
        if (settings_.correct_smoothing && !bent && goes_through) {
            // Totally reflected, but smoothing sent it through: mirror it on the polygon itself.
            direction = reflect(ray.direction, s.facing_normal);
        }
        const Lobe lobe{direction,
                        {radians(a.refract_cone_degrees), a.refract_cone_exponent},
                        !bent,  // totally reflected light stays on the ray's side
                        false,
                        RayKind::Refracted,
                        cones != nullptr ? &cones->refract : nullptr};
        const Rgb traced = gather(lobe, s, depth, rays, sample, weight);
        if (!split) {
            return traced;
        }
        result[channel] = traced[channel];
    }
    return result;
}

// The mean over the lobe's strata, taken in progressive order until the -Xr rule is met, or
// all of them with -Dx. The rule may stop early only where every ray so far saw one surface
// (SurfaceSeen) and, for a cone, four probes along its rim see it too: an edge can slip between a
// lobe's first rays, as between a pixel's first samples, most often where a glossy reflection
// runs off a polygon into the background. A diffuse lobe's hemisphere has no rim worth probing.
Rgb RayTracer::gather(const Lobe& lobe, const SurfacePoint& s, int depth, LobeRays rays,
                      SampleContext& sample, double weight) const {
    const bool distribute = rays == LobeRays::Distributed;
    const bool spread = lobe.diffuse || (distribute && lobe.cone.half_angle > 0.0);
    if (!spread) {
        const bool simple = rays == LobeRays::AxisSimple;
        return trace({s.position, lobe.axis, s.polygon}, lobe.kind, depth + 1, simple, sample,
                     weight);
    }
    const SamplingSettings& sampling = settings_.sampling;
    const std::uint32_t total = distribute ? ray_strata_.size() : 1;
    // The lobe's basis and cone edge, once for all its rays.
    std::optional<CosineHemisphereSampler> hemisphere;
    std::optional<ConeSampler> cone;
    if (lobe.diffuse) {
        hemisphere.emplace(lobe.axis);
    } else {
        cone.emplace(lobe.shape != nullptr ? *lobe.shape : ConeShape(lobe.cone), lobe.axis);
    }
    const auto direction_of = [&](std::uint32_t k) {
        double u1 = 0.0;
        double u2 = 0.0;
        const double j1 = sample.stream.uniform();
        const double j2 = sample.stream.uniform();
        ray_strata_.point(k, j1, j2, u1, u2);
        const Vec3 direction = lobe.diffuse ? (*hemisphere)(u1, u2) : (*cone)(u1, u2);
        return keep_on_side(direction, s.facing_normal, lobe.outside);
    };
    const auto take = [&](std::uint32_t k) {
        const Rgb value = trace({s.position, direction_of(k), s.polygon}, lobe.kind, depth + 1,
                                true, sample, weight);
        ++sample.tree.distributed_rays;
        return SeenSample<SurfaceSeen>{value, sample.last_seen};
    };
    const auto rim_agrees = [&](const SurfaceSeen& seen) {
        return lobe.diffuse || rim_sees(lobe, *cone, s, seen, sample);
    };
    return adaptive_mean(total, sampling.adaptive ? &sampling.ray_stop : nullptr, take, rim_agrees)
        .mean();
}

bool RayTracer::rim_sees(const Lobe& lobe, const ConeSampler& cone, const SurfacePoint& s,
                         const SurfaceSeen& seen, SampleContext& sample) const {
    const bool full = settings_.sampling.illuminate_distributed;  // as for the lobe's own rays
    for (const Vec3& on_rim : cone.rim()) {
        const Vec3 direction = keep_on_side(on_rim, s.facing_normal, lobe.outside);
        ++sample.tree.probes;
        if (!(first_surface({s.position, direction, s.polygon}, RayStart::Elsewhere, full,
                            sample) == seen)) {
            return false;
        }
    }
    return true;
}

}  // namespace rt
