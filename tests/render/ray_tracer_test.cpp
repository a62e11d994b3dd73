// The ray tree against independent computations: -R dispersion, the -Ds estimate of diffuse
// light against the form factor, and where distribution happens (maxdist, -Dd).
#include "rt/render/ray_tracer.h"

#include <cmath>
#include <numbers>

#include "rt/accel/brute_force.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

struct Traced {
    Rgb light;
    RayTreeCounts tree;
};

Traced trace_once(const Scene& scene, const ShadingSettings& settings, const Ray& ray,
                  std::uint32_t sample_index = 0) {
    const auto accel = make_brute_force(scene);
    const RayTracer tracer(scene, *accel, settings);
    SampleStream stream(settings.sampling.seed, 0, 0, sample_index);
    KindCounters counters;
    Traced out;
    SampleContext sample{stream, counters, out.tree, {}};
    out.light = tracer.trace(ray, RayKind::Eye, 1, false, sample);
    return out;
}

void add_square(test::SceneBuilder& b, const Vec3& centre, double half, const Vec3& normal,
                std::uint32_t attribute) {
    // A square in a plane z = const or y = const, by its normal.
    std::vector<Vec3> corners;
    if (normal.z != 0.0) {
        corners = {centre + Vec3{-half, -half, 0}, centre + Vec3{half, -half, 0},
                   centre + Vec3{half, half, 0}, centre + Vec3{-half, half, 0}};
    } else {
        corners = {centre + Vec3{-half, 0, -half}, centre + Vec3{half, 0, -half},
                   centre + Vec3{half, 0, half}, centre + Vec3{-half, 0, half}};
    }
    b.add_polygon(corners, normal, attribute);
}

// White light seen through a refracting plane with three indices (-R): each channel bends by its
// own index, so an emitter placed where only the red ray lands is seen in red only.
TEST(RayTracer, DashRSplitsWhiteLightIntoChannels) {
    test::SceneBuilder b;
    Attribute glass;
    glass.color = {1, 1, 1};
    glass.transmission = 1.0;
    glass.refraction_index = {1.2, 1.5, 1.8};
    Attribute lamp;
    lamp.color = {1, 1, 1};
    lamp.emission = 1.0;
    b.scene().attributes = {glass, lamp};
    b.scene().header.maxdepth = 2;
    add_square(b, {0, 0, 0}, 50.0, {0, 0, -1}, 0);
    const Ray ray{{-1, 0, -1}, normalize(Vec3{1, 0, 1})};  // 45 degrees, hits the origin
    ShadingSettings settings;
    settings.attenuate_rays = false;
    settings.sampling.distribute = false;
    // Where each channel's ray crosses z = 10: 10 tan(asin(sin 45 / n)).
    const auto landing = [](double n) {
        return 10.0 * std::tan(std::asin(std::sin(std::numbers::pi / 4) / n));
    };
    for (int channel = 0; channel < 3; ++channel) {
        test::SceneBuilder with_lamp = b;
        const double n = glass.refraction_index[channel];
        add_square(with_lamp, {landing(n), 0, 10}, 0.3, {0, 0, -1}, 1);
        const Rgb got = trace_once(with_lamp.scene(), settings, ray).light;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(got[c], c == channel ? 1.0 : 0.0, 1e-12) << channel << " " << c;
        }
    }
}

// Form factor from a point to a parallel square of half side s centred at height h above it.
double form_factor_to_centred_square(double s, double h) {
    const double x = s / h;
    const double r = std::sqrt(1.0 + x * x);
    return 4.0 * (2.0 * x / r * std::atan(x / r)) / (2.0 * std::numbers::pi);
}

// -Ds: no shadow feelers, light arrives only along diffuse rays that find the emitter. Their
// mean converges to the emitter's radiance times the form factor (Lambert), whatever the seed.
TEST(RayTracer, WithoutShadowFeelersDiffuseLightConvergesToTheFormFactor) {
    test::SceneBuilder b;
    Attribute floor;
    floor.color = {1, 1, 1};
    floor.diffuse = 1.0;
    Attribute lamp;
    lamp.color = {1, 1, 1};
    lamp.emission = 1.0;
    b.scene().attributes = {floor, lamp};
    b.scene().header.maxdepth = 2;
    b.scene().header.maxdist = 1;
    b.scene().view.sample_resolution_x = 16;
    b.scene().view.sample_resolution_y = 16;
    add_square(b, {0, 0, 0}, 100.0, {0, 1, 0}, 0);
    add_square(b, {0, 2, 0}, 1.0, {0, -1, 0}, 1);
    ShadingSettings settings;
    settings.shadow_feelers = false;
    settings.attenuate_rays = false;
    settings.sampling.adaptive = false;
    const Ray down{{0.001, 1, 0.002}, {0, -1, 0}};
    double sum = 0.0;
    constexpr int kSamples = 200;  // x 256 diffuse rays each
    for (std::uint32_t k = 0; k < kSamples; ++k) {
        const Traced t = trace_once(b.scene(), settings, down, k);
        EXPECT_EQ(t.tree.distributed_rays, 256U);
        sum += t.light.g;
    }
    EXPECT_NEAR(sum / kSamples, form_factor_to_centred_square(1.0, 2.0), 0.005);
}

// maxdist is the depth down to which rays are distributed; -Dd distributes nothing.
TEST(RayTracer, RaysAreDistributedDownToMaxdistOnly) {
    test::SceneBuilder b;
    Attribute glossy;
    glossy.color = {1, 1, 1};
    glossy.specular = 0.5;
    glossy.reflect_cone_degrees = 10.0;
    glossy.reflect_cone_exponent = 4.0;
    b.scene().attributes = {glossy};
    b.scene().header.maxdepth = 3;
    b.scene().view.sample_resolution_x = 2;
    b.scene().view.sample_resolution_y = 2;
    // Two facing mirrors: every reflected ray hits again.
    add_square(b, {0, 0, 0}, 100.0, {0, 1, 0}, 0);
    add_square(b, {0, 5, 0}, 100.0, {0, -1, 0}, 0);
    const Ray down{{0, 4, 0}, normalize(Vec3{0.1, -1, 0})};
    ShadingSettings settings;
    settings.sampling.adaptive = false;
    settings.sampling.illuminate_distributed = true;  // -I: distributed rays distribute again
    b.scene().header.maxdist = 0;
    EXPECT_EQ(trace_once(b.scene(), settings, down).tree.distributed_rays, 0U);
    b.scene().header.maxdist = 1;
    EXPECT_EQ(trace_once(b.scene(), settings, down).tree.distributed_rays, 4U);
    b.scene().header.maxdist = 2;
    EXPECT_EQ(trace_once(b.scene(), settings, down).tree.distributed_rays, 4U + 4U * 4U);
    // Without -I, the rays of a distribution do not distribute again.
    settings.sampling.illuminate_distributed = false;
    EXPECT_EQ(trace_once(b.scene(), settings, down).tree.distributed_rays, 4U);
    settings.sampling.distribute = false;  // -Dd
    EXPECT_EQ(trace_once(b.scene(), settings, down).tree.distributed_rays, 0U);
}

}  // namespace
}  // namespace rt
