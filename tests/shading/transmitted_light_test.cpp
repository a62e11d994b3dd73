// -T: a light behind a non-opaque polygon shines through it in a cos^tpow lobe around the refracted
// continuation of the viewing ray (docs/illumination-models.md), against Snell's law worked by
// hand.
#include <cmath>
#include <numbers>

#include "rt/accel/brute_force.h"
#include "rt/shading/illumination.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr double kIndex = 1.5;
constexpr double kTransmission = 0.6;
constexpr double kTpow = 4.0;
constexpr Rgb kGlassColour{0.5, 0.6, 0.7};
constexpr Rgb kLightColour{1.0, 0.9, 0.8};
constexpr double kEmission = 2.0;

// A glass square (attribute 0) in y = 0 with its normal up, neither diffuse nor ambient so that
// only transmitted light is left, and a small emissive triangle (attribute 1) centred at `light`.
struct GlassAndLight {
    explicit GlassAndLight(const Vec3& light) {
        Attribute glass;
        glass.color = kGlassColour;
        glass.transmission = kTransmission;
        glass.transmit_exponent = kTpow;
        glass.refraction_index = {kIndex, kIndex, kIndex};
        Attribute lamp;
        lamp.color = kLightColour;
        lamp.emission = kEmission;
        builder.scene().attributes = {glass, lamp};
        builder.add_polygon({{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}, {0, 1, 0}, 0);
        // Corners around `light` whose mean is `light`: the lghtick 2 point source sits there.
        builder.add_polygon(
            {light + Vec3{-0.1, 0, -0.1}, light + Vec3{0.1, 0, -0.1}, light + Vec3{0.0, 0, 0.2}},
            {0, light.y > 0 ? -1.0 : 1.0, 0}, 1);
        builder.scene().header.lghtick = 2;
    }

    // Light leaving the glass at the origin toward an eye at `eye`.
    Rgb shade_origin_seen_from(const Vec3& eye, const ShadingSettings& settings,
                               bool highlights = true) {
        const Scene& scene = builder.scene();
        const auto accel = make_brute_force(scene);
        const std::vector<PointLight> lights = collect_point_lights(scene, 2);
        const IlluminationContext context{scene, *accel, settings, lights, 1e-9};
        const Vec3 view = normalize(eye);
        const Ray ray{eye, -view};
        const SurfacePoint s = describe_hit(scene, settings, ray, Hit{length(eye), 0});
        TraceCounters counters;
        return local_illumination(context, s, view, highlights, counters);
    }

    test::SceneBuilder builder;
};

ShadingSettings with_dash_t() {
    ShadingSettings settings;
    settings.far_side_feelers = true;
    return settings;
}

// What the light brings to the origin: its intensity under the -A fall-off.
Rgb received_from(const Vec3& light) {
    const ShadingSettings defaults;
    return kLightColour * (kEmission * defaults.attenuation(length(light)));
}

void expect_near(const Rgb& got, const Rgb& want, double tolerance) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], tolerance) << "channel " << c;
    }
}

TEST(TransmittedLight, StraightThroughUnderNormalIncidence) {
    // Eye straight above, light straight below: the refracted ray goes on down, lobe cos^4(0) = 1.
    const Vec3 light{0, -20, 0};
    GlassAndLight setup(light);
    const Rgb got = setup.shade_origin_seen_from({0, 5, 0}, with_dash_t());
    expect_near(got, received_from(light) * kGlassColour * kTransmission, 1e-12);
}

TEST(TransmittedLight, LobeIsCosToTheTpowAroundTheRefractedRay) {
    // Eye straight above, light 30 degrees off the downward continuation.
    const double off = std::numbers::pi / 6.0;
    const Vec3 light = Vec3{std::sin(off), -std::cos(off), 0} * 20.0;
    GlassAndLight setup(light);
    const Rgb got = setup.shade_origin_seen_from({0, 5, 0}, with_dash_t());
    const double lobe = std::pow(std::cos(off), kTpow);
    expect_near(got, received_from(light) * kGlassColour * (kTransmission * lobe), 1e-12);
}

TEST(TransmittedLight, LobeFollowsSnellsLawForAnObliqueEye) {
    // Eye 50 degrees from the normal: the ray bends to asin(sin 50 / 1.5) on the far side. A light
    // on that refracted line gets the full lobe; one on the unbent line does not.
    const double incidence = 50.0 * std::numbers::pi / 180.0;
    const double bent = std::asin(std::sin(incidence) / kIndex);
    const Vec3 eye = Vec3{-std::sin(incidence), std::cos(incidence), 0} * 5.0;
    const Vec3 on_refracted = Vec3{std::sin(bent), -std::cos(bent), 0} * 20.0;
    const Vec3 on_unbent = Vec3{std::sin(incidence), -std::cos(incidence), 0} * 20.0;

    GlassAndLight refracted_setup(on_refracted);
    const Rgb full = refracted_setup.shade_origin_seen_from(eye, with_dash_t());
    expect_near(full, received_from(on_refracted) * kGlassColour * kTransmission, 1e-12);

    GlassAndLight unbent_setup(on_unbent);
    const Rgb partial = unbent_setup.shade_origin_seen_from(eye, with_dash_t());
    const double lobe = std::pow(std::cos(incidence - bent), kTpow);
    expect_near(partial, received_from(on_unbent) * kGlassColour * (kTransmission * lobe), 1e-12);
}

TEST(TransmittedLight, NothingBeyondTheCriticalAngleFromInside) {
    // Seen from below (inside the glass, index 1.5 -> 1), light above. At 30 degrees the ray leaves
    // at asin(1.5 sin 30) = 48.6 degrees; at 60 degrees it is reflected totally: no light through.
    const Vec3 light{0, 20, 0};
    GlassAndLight setup(light);
    const double steep = 30.0 * std::numbers::pi / 180.0;
    const Rgb through = setup.shade_origin_seen_from(
        Vec3{std::sin(steep), -std::cos(steep), 0} * 5.0, with_dash_t());
    const double leaving = std::asin(kIndex * std::sin(steep));
    const double lobe = std::pow(std::cos(leaving), kTpow);  // the light is along the normal
    expect_near(through, received_from(light) * kGlassColour * (kTransmission * lobe), 1e-12);

    const double grazing = 60.0 * std::numbers::pi / 180.0;
    const Rgb reflected = setup.shade_origin_seen_from(
        Vec3{std::sin(grazing), -std::cos(grazing), 0} * 5.0, with_dash_t());
    EXPECT_EQ(reflected, Rgb{});
}

TEST(TransmittedLight, OnlyWithDashTAndOnlyAtFullyIlluminatedHits) {
    const Vec3 light{0, -20, 0};
    GlassAndLight setup(light);
    EXPECT_EQ(setup.shade_origin_seen_from({0, 5, 0}, ShadingSettings{}), Rgb{});
    EXPECT_EQ(setup.shade_origin_seen_from({0, 5, 0}, with_dash_t(), false), Rgb{});
}

TEST(TransmittedLight, OpaqueUnderDashPoWhenSmoothShaded) {
    const Vec3 light{0, -20, 0};
    GlassAndLight setup(light);
    setup.builder.smooth_vertex_normals();
    ShadingSettings settings = with_dash_t();
    EXPECT_GT(setup.shade_origin_seen_from({0, 5, 0}, settings).r, 0.0);
    settings.smooth_shaded_opaque = true;
    EXPECT_EQ(setup.shade_origin_seen_from({0, 5, 0}, settings), Rgb{});
}

}  // namespace
}  // namespace rt
