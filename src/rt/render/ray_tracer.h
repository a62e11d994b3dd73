// The ray tree (manual 1.3): a ray finds its first polygon, takes the local illumination there,
// and spawns reflected and refracted rays (and, without shadow feelers, diffuse rays) down to the
// header's maxdepth. Down to maxdist they are distributed in their cones by the cos^n law, as
// many as the adaptive rule (-Xr) asks for; deeper, or with -Dd, one ray each.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
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
#include "rt/shading/shadow_feeler.h"
#include "rt/shading/surface_point.h"

namespace rt {

/// What one sample's ray tree did, for -dx.
struct RayTreeCounts {
    std::uint32_t distributed_intersections = 0;  ///< hits that distributed rays
    std::uint32_t distributed_rays = 0;           ///< rays they sent
    std::uint32_t probes = 0;                     ///< rays along lobes' rims (adaptive rule)
};

/// What a ray met, as the adaptive rule compares rays: the polygon (kNoPolygon for none) and how
/// many polygons the shadow feelers from its hit met on their way to the lights. Rays that agree
/// on both see one surface in one light: no polygon's edge and no shadow's edge between them.
struct SurfaceSeen {
    static constexpr std::int64_t kNoPolygon = -1;
    std::int64_t polygon = kNoPolygon;
    std::uint64_t feeler_stops = 0;
    friend bool operator==(const SurfaceSeen&, const SurfaceSeen&) = default;
};

/// The state of one sample being traced: its random numbers and counters.
struct SampleContext {
    SampleStream& stream;
    KindCounters& counters;
    RayTreeCounts& tree;
    SurfaceSeen last_seen;  ///< what the last traced ray met
    /// The feelers from the sample's eye hit, planned and asked beforehand (eye_feelers), one a
    /// light; empty for none.
    std::span<const FeelerAnswer> eye_feelers = {};
};

/// The room RayTracer::eye_feelers works in, kept by its caller from call to call: a render asks
/// for every run of eye rays, several hundred thousand times.
struct EyeFeelerRoom {
    std::vector<SurfacePoint> points;  ///< the hits' surface points
    std::vector<std::size_t> ray_of;   ///< the ray of each point
    RayPacket packet;
    PacketHits found;
};

/// Where a ray starts: from the eye, through the screen (the eye rays and the adaptive rule's
/// probes of neighbouring pixels, which a z-buffer may answer), or anywhere else.
enum class RayStart { Eye, Elsewhere };

class RayTracer {
public:
    RayTracer(const Scene& scene, const Accelerator& accel, const ShadingSettings& settings);

    /// Once *stop is set, every ray returns black at once without tracing: a ray tree of any
    /// size ends within one ray's time. The caller must then throw away what it was computing.
    void abandon_when(const std::atomic<bool>* stop) { stop_ = stop; }

    /// Intensity arriving along the ray (unit direction) from its origin's side; depth 1 is the
    /// eye ray. Light picked up at distance d is attenuated by the -A formula unless -Da.
    /// `distributed`: the ray is one of a distribution, or descends from one (without -I it gets
    /// the simple model).
    /// `weight`: the product of the reflection and transmission coefficients along the ray's path
    /// from the eye (1 for an eye ray), which the weight cutoff (--cutoff) compares.
    Rgb trace(const Ray& ray, RayKind kind, int depth, bool distributed, SampleContext& sample,
              double weight = 1.0) const;

    /// The nearest hits of eye rays (nearest_hit with RayStart::Eye), asked eight at a time
    /// through the accelerator's packet walk: rays of neighbouring samples share its path, and
    /// each answer is exactly the single ray's. The walk's counters go to `counters`.
    void eye_ray_hits(std::span<const Ray> rays, std::span<std::optional<Hit>> hits,
                      TraceCounters& counters) const;
    /// The number of answers eye_feelers gives a ray: one a light, or none when the feelers are
    /// not found beforehand (no shadow feelers; fuzzy ones, -F, which draw at random; or a
    /// method without a packet walk, Accelerator::walks_packets).
    std::size_t eye_feelers_per_ray() const { return feelers_ahead_ ? lights_.size() : 0; }
    /// The answers to the first queries of the shadow feelers that shading the eye rays' `hits`
    /// will send, asked eight at a time through the accelerator's packet walk: feelers from
    /// neighbouring hits toward one light point are coherent rays. answers[ray *
    /// eye_feelers_per_ray() + light] is that of the feeler from the ray's hit toward the light,
    /// or nothing where shading sends none. The walk's counters go to `counters`.
    void eye_feelers(std::span<const Ray> rays, std::span<const std::optional<Hit>> hits,
                     std::span<FeelerAnswer> answers, TraceCounters& counters,
                     EyeFeelerRoom& room) const;
    /// trace for an eye ray whose nearest hit eye_ray_hits has found (and its feelers, if
    /// sample.eye_feelers holds them, eye_feelers): the same value, random numbers and counters,
    /// the walks' own counters apart.
    Rgb trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit, SampleContext& sample) const;

    /// What a ray meets first: its polygon, and its hit's shadow feelers, without shading it or
    /// tracing further (the adaptive rule's probes). `full` as for a ray that is not distributed
    /// (the full model's feelers, -T).
    SurfaceSeen first_surface(const Ray& ray, RayStart start, bool full,
                              SampleContext& sample) const;

private:
    struct Lobe;
    /// The accelerator's nearest hit beyond epsilon: eye rays through its eye-ray entry point.
    std::optional<Hit> nearest_hit(const Ray& ray, RayStart start, TraceCounters& counters) const;
    /// trace for a ray whose nearest hit (nearest_hit) is found already, in a packet.
    Rgb trace_found(const Ray& ray, const std::optional<Hit>& hit, RayKind kind, int depth,
                    bool distributed, SampleContext& sample, double weight) const;
    /// trace from the ray's nearest hit on: local illumination and the subtree.
    Rgb shade(const Ray& ray, const std::optional<Hit>& hit, RayKind kind, int depth,
              bool distributed, SampleContext& sample, double weight) const;
    /// How the lobes at one hit send their rays.
    enum class LobeRays {
        Distributed,  ///< a distribution in each cone, as many rays as -Xr asks for
        Axis,         ///< one ray along each lobe's axis (-Dd, or deeper than maxdist)
        AxisSimple,   ///< one ray along the axis, from the hit of a distributed ray without -I:
                      ///< it keeps the simple model
    };
    /// Whether rays along the cone's rim see `seen` too (see gather).
    bool rim_sees(const Lobe& lobe, const ConeSampler& cone, const SurfacePoint& s,
                  const SurfaceSeen& seen, SampleContext& sample) const;
    Rgb secondary_rays(const Ray& ray, const SurfacePoint& s, int depth, bool full,
                       SampleContext& sample, double weight) const;
    Rgb refracted_rays(const Ray& ray, const SurfacePoint& s, int depth, LobeRays rays,
                       SampleContext& sample, double weight) const;
    /// Whether a branch of this weight is traced: all are, unless --cutoff sets a threshold.
    bool worth_tracing(double weight) const { return !(weight < settings_.weight_cutoff); }
    /// The mean intensity over a lobe: one ray along its axis, or a distribution of rays (a
    /// diffuse lobe always spreads its rays over the hemisphere).
    Rgb gather(const Lobe& lobe, const SurfacePoint& s, int depth, LobeRays rays,
               SampleContext& sample, double weight) const;

    const Scene& scene_;
    const Accelerator& accel_;
    const std::atomic<bool>* stop_ = nullptr;
    ShadingSettings settings_;
    std::vector<PointLight> lights_;
    ProgressiveStrata ray_strata_;  ///< the strata of distributed rays at one intersection
    double epsilon_ = 1e-9;
    int max_depth_ = 1;
    double max_distributed_depth_ = 0.0;  ///< the header's maxdist
    /// Per attribute, its reflection and refraction cones' shapes, worked out once.
    struct MaterialCones {
        ConeShape reflect;
        ConeShape refract;
    };
    std::vector<MaterialCones> cones_;
    /// The cones of the attribute `s` shades with; null for an attribute not of the scene.
    const MaterialCones* cones_of(const SurfacePoint& s) const;
    bool diffuse_rays_ = false;   ///< no shadow feelers: light arrives by diffuse rays
    bool feelers_ahead_ = false;  ///< eye_feelers finds answers (see eye_feelers_per_ray)
};

}  // namespace rt
