// The adaptive rule's one-surface condition (docs/rendering.md, "Adaptive supersampling"): rays
// see one surface only on one polygon in one light, and a lobe stops early only if the probes
// along its rim see its surface too.
#include <memory>
#include <numbers>

#include "rt/accel/brute_force.h"
#include "rt/render/ray_tracer.h"
#include "rt/sampling/directions.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// A square of half-size `half` centred on `centre`, facing along `normal` (any direction).
void add_square(test::SceneBuilder& b, const Vec3& centre, double half, const Vec3& normal,
                std::uint32_t attribute) {
    Vec3 u;
    Vec3 v;
    orthonormal_basis(normalize(normal), u, v);
    b.add_polygon({centre - u * half - v * half, centre + u * half - v * half,
                   centre + u * half + v * half, centre - u * half + v * half},
                  normal, attribute);
}

struct Traced {
    SurfaceSeen seen;    ///< what the traced ray met
    SurfaceSeen probed;  ///< what first_surface says of the same ray
    RayTreeCounts tree;
};

Traced trace_once(const Scene& scene, const ShadingSettings& settings, const Ray& ray) {
    const auto accel = make_brute_force(scene);
    const RayTracer tracer(scene, *accel, settings);
    SampleStream stream(settings.sampling.seed, 0, 0, 0);
    KindCounters counters;
    Traced out;
    SampleContext sample{stream, counters, out.tree, {}};
    tracer.trace(ray, RayKind::Eye, 1, false, sample);
    out.seen = sample.last_seen;
    out.probed = tracer.first_surface(ray, RayStart::Eye, true, sample);
    return out;
}

// A floor lit by a small lamp overhead, with a blocker casting a shadow on part of it.
TEST(AdaptiveRule, LightAndShadowOnOnePolygonAreTwoSurfaces) {
    test::SceneBuilder b;
    Attribute floor;
    floor.color = {1, 1, 1};
    floor.diffuse = 1.0;
    Attribute lamp;
    lamp.color = {1, 1, 1};
    lamp.emission = 1.0;
    b.scene().attributes = {floor, lamp};
    b.scene().header.lghtick = 2;  // a point light at the lamp's centre
    const std::uint32_t ground =
        b.add_polygon({{-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}}, {0, 1, 0}, 0);
    add_square(b, {0, 10, 0}, 0.5, {0, -1, 0}, 1);
    add_square(b, {3, 5, 0}, 1.0, {0, -1, 0}, 0);  // its shadow falls around x = 6
    ShadingSettings settings;
    const Traced lit = trace_once(b.scene(), settings, {{-5, 3, 0}, normalize(Vec3{0, -1, 0})});
    const Traced shadowed = trace_once(b.scene(), settings, {{6, 3, 0}, normalize(Vec3{0, -1, 0})});
    EXPECT_EQ(lit.seen.polygon, ground);
    EXPECT_EQ(shadowed.seen.polygon, ground);
    EXPECT_EQ(lit.seen.feeler_stops, 0U);
    EXPECT_EQ(shadowed.seen.feeler_stops, 1U);
    EXPECT_FALSE(lit.seen == shadowed.seen);
    // A probe sees what the traced ray saw.
    EXPECT_EQ(lit.probed, lit.seen);
    EXPECT_EQ(shadowed.probed, shadowed.seen);
}

// A glossy floor reflecting an empty sky: its lobe's first quarter of rays all miss. Alone, the
// lobe stops there after probing its rim; with a small polygon on the rim, it takes every ray.
TEST(AdaptiveRule, ALobeStopsEarlyOnlyIfItsRimSeesItsSurface) {
    test::SceneBuilder b;
    Attribute glossy;
    glossy.color = {1, 1, 1};
    glossy.specular = 0.5;  // no diffuse: without lights that would send diffuse rays too
    glossy.reflect_cone_degrees = 10.0;
    glossy.reflect_cone_exponent = 4.0;
    b.scene().attributes = {glossy};
    b.scene().header.maxdepth = 2;
    b.scene().header.maxdist = 1;
    b.scene().view.sample_resolution_x = 4;
    b.scene().view.sample_resolution_y = 4;
    b.add_polygon({{-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}}, {0, 1, 0}, 0);
    const Ray down{{0, 3, 0}, {0, -1, 0}};  // mirrored straight up
    ShadingSettings settings;
    const Traced alone = trace_once(b.scene(), settings, down);
    EXPECT_EQ(alone.tree.distributed_rays, 4U);  // a quarter of 16
    EXPECT_EQ(alone.tree.probes, 4U);

    // A polygon far smaller than the cone, where the first rim probe looks.
    const CosPowerCone cone{10.0 * std::numbers::pi / 180.0, 4.0};
    const Vec3 rim = sample_cone(cone, {0, 1, 0}, 1.0, 0.0);
    add_square(b, rim * 5.0, 0.01, -rim, 0);
    const Traced edged = trace_once(b.scene(), settings, down);
    EXPECT_EQ(edged.tree.distributed_rays, 16U);
    EXPECT_EQ(edged.tree.probes, 1U);  // the first probe found it

    settings.sampling.adaptive = false;  // -Dx: every ray, no probes
    const Traced every = trace_once(b.scene(), settings, down);
    EXPECT_EQ(every.tree.distributed_rays, 16U);
    EXPECT_EQ(every.tree.probes, 0U);
}

}  // namespace
}  // namespace rt
