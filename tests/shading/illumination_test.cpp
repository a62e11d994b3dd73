// The local illumination model against numbers worked out by hand.
#include "rt/shading/illumination.h"

#include <cmath>

#include "rt/accel/brute_force.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// A diffuse floor square (attribute 0) in y = 0, a small emissive triangle (attribute 1) at
// height h above the origin, facing down, and optionally a blocker between them.
struct FloorAndLight {
    explicit FloorAndLight(double h, bool with_blocker = false, double blocker_t = 0.0) {
        Attribute floor;
        floor.color = {0.5, 0.6, 0.7};
        floor.diffuse = 0.8;
        floor.ambient = 0.1;
        Attribute light;
        light.color = {1.0, 0.9, 0.8};
        light.emission = 2.0;
        Attribute glass;
        glass.color = {0.5, 1.0, 1.0};
        glass.transmission = blocker_t;
        builder.scene().attributes = {floor, light, glass};
        builder.add_polygon({{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}, {0, 1, 0}, 0);
        builder.add_polygon({{-0.1, h, -0.1}, {0.1, h, -0.1}, {0.0, h, 0.2}}, {0, -1, 0}, 1);
        if (with_blocker) {
            const double y = h / 2;
            builder.add_polygon({{-1, y, -1}, {-1, y, 1}, {1, y, 1}, {1, y, -1}}, {0, 1, 0}, 2);
        }
        builder.scene().header.lghtick = 2;
    }
    Rgb shade_origin(const ShadingSettings& settings) {
        const Scene& scene = builder.scene();
        const auto accel = make_brute_force(scene);
        const std::vector<PointLight> lights = collect_point_lights(scene, 2);
        const IlluminationContext context{scene, *accel, settings, lights, 1e-9};
        const Ray down{{0, 5, 0}, {0, -1, 0}};
        const SurfacePoint s = describe_hit(scene, settings, down, Hit{5.0, 0});
        TraceCounters counters;
        return local_illumination(context, s, {0, 1, 0}, true, counters);
    }
    test::SceneBuilder builder;
};

TEST(Illumination, DiffuseFloorUnderOneShadowFeelerLight) {
    const double h = 20.0;
    FloorAndLight setup(h);
    const ShadingSettings settings;  // -A 200,1
    const Rgb got = setup.shade_origin(settings);
    const double fall_off = 1.0 / (h / 200.0 + 1.0);
    const Rgb light{2.0, 1.8, 1.6};
    // The light stands at the triangle's centre, straight above: cos = 1.
    for (int c = 0; c < 3; ++c) {
        const double colour = setup.builder.scene().attributes[0].color[c];
        const double expected = 0.1 * colour + 0.8 * colour * light[c] * fall_off;
        EXPECT_NEAR(got[c], expected, 1e-12) << "channel " << c;
    }
}

TEST(Illumination, DashDlTurnsOffTheLightsAttenuation) {
    FloorAndLight setup(20.0);
    ShadingSettings settings;
    settings.attenuate_feelers = false;
    const Rgb got = setup.shade_origin(settings);
    EXPECT_NEAR(got.r, 0.1 * 0.5 + 0.8 * 0.5 * 2.0, 1e-12);
}

TEST(Illumination, OpaqueBlockerCastsAShadow) {
    FloorAndLight setup(20.0, true, 0.0);
    const Rgb got = setup.shade_origin(ShadingSettings{});
    EXPECT_NEAR(got.r, 0.1 * 0.5, 1e-12);  // ambient only
}

TEST(Illumination, TransparentBlockerFiltersUnlessDashDt) {
    FloorAndLight setup(20.0, true, 0.5);
    const Rgb filtered = setup.shade_origin(ShadingSettings{});
    const double fall_off = 1.0 / (20.0 / 200.0 + 1.0);
    // The glass passes t * colour: 0.25 of red, 0.5 of green.
    EXPECT_NEAR(filtered.r, 0.05 + 0.8 * 0.5 * 2.0 * 0.25 * fall_off, 1e-12);
    EXPECT_NEAR(filtered.g, 0.06 + 0.8 * 0.6 * 1.8 * 0.5 * fall_off, 1e-12);
    ShadingSettings stop;
    stop.feelers_stop_at_transparent = true;
    EXPECT_NEAR(setup.shade_origin(stop).r, 0.05, 1e-12);
}

TEST(Illumination, LightsShareTheirIntensityAmongVertices) {
    FloorAndLight setup(20.0);
    const std::vector<PointLight> centres = collect_point_lights(setup.builder.scene(), 2);
    const std::vector<PointLight> vertices = collect_point_lights(setup.builder.scene(), 1);
    ASSERT_EQ(centres.size(), 1U);
    ASSERT_EQ(vertices.size(), 3U);
    EXPECT_NEAR(vertices[0].intensity.r * 3.0, centres[0].intensity.r, 1e-15);
    EXPECT_TRUE(collect_point_lights(setup.builder.scene(), 0).empty());
}

}  // namespace
}  // namespace rt
