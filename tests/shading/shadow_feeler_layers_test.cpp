// How far a shadow feeler goes through transparent polygons: each filters the light by its colour
// times its transmission; past 64 of them the light is taken as lost.
#include <cmath>

#include "rt/accel/brute_force.h"
#include "rt/shading/shadow_feeler.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// `layers` panes (colour 1, transmission 0.99) stacked between z = 1 and z = 9.
Scene panes(int layers) {
    test::SceneBuilder b;
    Attribute pane;
    pane.color = {1.0, 1.0, 1.0};
    pane.transmission = 0.99;
    b.scene().attributes = {pane};
    for (int i = 0; i < layers; ++i) {
        const double z = 1.0 + 8.0 * i / layers;
        b.add_polygon({{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}}, {0, 0, -1});
    }
    return b.scene();
}

Rgb through(const Scene& scene, const Vec3& from, const Vec3& span) {
    const auto accel = make_brute_force(scene);
    const ShadingSettings settings;
    const FeelerContext context{scene, *accel, settings, 1e-9, nullptr};
    TraceCounters counters;
    return feeler_transmittance(context, from, span, 1u << 30, counters);
}

TEST(ShadowFeelerLayers, SixtyFourPanesFilterTheLight) {
    const Rgb got = through(panes(64), {0, 0, 0}, {0, 0, 10});
    EXPECT_NEAR(got.g, std::pow(0.99, 64), 1e-12);
}

TEST(ShadowFeelerLayers, PastSixtyFourPanesTheLightIsLost) {
    EXPECT_EQ(through(panes(65), {0, 0, 0}, {0, 0, 10}), Rgb{});
}

TEST(ShadowFeelerLayers, AFeelerNoLongerThanEpsilonBringsNothing) {
    EXPECT_EQ(through(panes(0), {0, 0, 0}, {0, 0, 1e-10}), Rgb{});
    EXPECT_EQ(through(panes(0), {0, 0, 0}, {0, 0, 1e-3}), (Rgb{1, 1, 1}));
}

}  // namespace
}  // namespace rt
