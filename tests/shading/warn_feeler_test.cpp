// Warn lights as the shadow feeler applies them (-Wr -Wc -Wt): the light a point receives from a
// ceiling emitter, against cos^pow of the angles worked out by hand.
#include <cmath>

#include "rt/accel/brute_force.h"
#include "rt/shading/shadow_feeler.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr double kPow = 4.0;
constexpr double kHeight = 10.0;
constexpr Rgb kIntensity{1.0, 0.5, 0.25};

// A small triangle facing down (pow 4, emission 1) centred at (x, kHeight, 0), and nothing else.
struct CeilingLight {
    explicit CeilingLight(double x) : centre{x, kHeight, 0.0} {
        Attribute lamp;
        lamp.color = kIntensity;
        lamp.emission = 1.0;
        lamp.specular_exponent = kPow;
        builder.scene().attributes = {lamp};
        builder.add_polygon(
            {centre + Vec3{-0.1, 0, -0.1}, centre + Vec3{0.1, 0, -0.1}, centre + Vec3{0.0, 0, 0.2}},
            {0, -1, 0}, 0);
    }

    Rgb received_at(const Vec3& point, const WarnSettings& warn) {
        ShadingSettings settings;
        settings.attenuate_feelers = false;  // leave the Warn factor alone
        settings.warn = warn;
        const Scene& scene = builder.scene();
        const auto accel = make_brute_force(scene);
        const FeelerContext context{scene, *accel, settings, 1e-9, nullptr};
        const PointLight light{centre, kIntensity, 0};
        TraceCounters counters;
        return feel_light(context, point, light, counters);
    }

    Vec3 centre;
    test::SceneBuilder builder;
};

// cos^pow of the angle between straight down and the line from `from` to `point`.
double rogers(const Vec3& from, const Vec3& point) {
    return std::pow(dot(normalize(point - from), Vec3{0, -1, 0}), kPow);
}

void expect_near(const Rgb& got, const Rgb& want) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], 1e-12) << "channel " << c;
    }
}

TEST(WarnFeeler, WithoutWarnLightsEveryDirectionGetsTheSame) {
    CeilingLight light(6.0);
    expect_near(light.received_at({0, 0, 0}, {}), kIntensity);
}

TEST(WarnFeeler, RogersWeighsTheLightByCosToThePow) {
    CeilingLight light(6.0);
    const WarnSettings dash_wr{WarnMode::Rogers, 0.0, 0.0};
    const Vec3 point{0, 0, 0};
    expect_near(light.received_at(point, dash_wr), kIntensity * rogers(light.centre, point));
    expect_near(light.received_at({6, 0, 0}, dash_wr), kIntensity);  // straight below
}

TEST(WarnFeeler, ConicalCutsTheLightOffOutsideItsCone) {
    // The point at x = 0 is atan(6 / 10) = 31 degrees off the normal.
    CeilingLight light(6.0);
    const Vec3 point{0, 0, 0};
    const WarnSettings wide{WarnMode::Conical, 0.6, 0.0};
    expect_near(light.received_at(point, wide), kIntensity * rogers(light.centre, point));
    const WarnSettings narrow{WarnMode::Conical, 0.5, 0.0};
    expect_near(light.received_at(point, narrow), Rgb{});
}

TEST(WarnFeeler, ThibadeauLightsOnlyWhatSeesTheSourceThroughThePolygon) {
    // The source moves 1 above the polygon (a triangle reaching 0.067 either side of its centre
    // along z = 0). The line to it from x = 0.5 under a light at x = 0.502 crosses the polygon's
    // plane at x = 0.5018, through the triangle; from x = 0 under a light at x = 6, at x = 5.45,
    // beside it.
    const double displacement = 1.0;
    const WarnSettings dash_wt{WarnMode::Thibadeau, 0.0, displacement};
    CeilingLight near_light(0.502);
    const Vec3 point{0.5, 0, 0};
    const Vec3 displaced = near_light.centre + Vec3{0, displacement, 0};
    expect_near(near_light.received_at(point, dash_wt), kIntensity * rogers(displaced, point));
    CeilingLight far_light(6.0);
    expect_near(far_light.received_at({0, 0, 0}, dash_wt), Rgb{});
}

TEST(WarnFeeler, NothingReachesTheLightsOwnPosition) {
    CeilingLight light(6.0);
    expect_near(light.received_at(light.centre, {}), Rgb{});
}

}  // namespace
}  // namespace rt
