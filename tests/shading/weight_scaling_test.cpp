// -K weight scaling on the attributes printed in the manual (2.3).
#include "rt/shading/weight_scaling.h"

#include <vector>

#include <gtest/gtest.h>

namespace rt {
namespace {

// The manual's first three attributes: colour, pow tpow, e a d s t, index.
Attribute manual_attribute(int index) {
    Attribute a;
    a.ambient = 0.05;
    a.refraction_index = {1.05, 1.05, 1.05};
    switch (index) {
        case 0:
            a.color = {0.0, 0.2, 0.98};
            a.diffuse = 0.9;
            a.specular = 0.1;
            break;
        case 1:
            a.color = {0.8, 0.2, 0.0};
            a.diffuse = 0.8;
            a.specular = 0.4;
            break;
        default:
            a.color = {0.8, 0.03, 0.02};
            a.diffuse = 0.3;
            a.specular = 0.6;
            a.transmission = 0.99;
            a.refraction_index = {1.5, 1.5, 1.5};
            break;
    }
    return a;
}

// One white light (L = 1), under -Ds (no feelers) and -Dr (no reflection) or not.
constexpr Rgb kOneWhiteLight{1.0, 0.9, 0.8};

ShadingSettings switches(bool feelers, bool reflection) {
    ShadingSettings settings;
    settings.shadow_feelers = feelers;
    settings.reflection = reflection;
    return settings;
}

struct Case {
    int attribute;
    bool feelers;
    bool reflection;
    double bound;
};

TEST(WeightScaling, ManualAttributesWithAndWithoutDrDs) {
    // bound = e + a + d*(feelers ? L : 1) + s*(feelers ? L : 0) + (reflection ? s : 0) + t, L = 1.
    const Case cases[] = {
        {0, true, true, 0.05 + 0.9 + 0.1 + 0.1},
        {0, true, false, 0.05 + 0.9 + 0.1},
        {0, false, true, 0.05 + 0.9 + 0.1},
        {0, false, false, 0.05 + 0.9},
        {1, true, true, 0.05 + 0.8 + 0.4 + 0.4},
        {1, true, false, 0.05 + 0.8 + 0.4},
        {1, false, true, 0.05 + 0.8 + 0.4},
        {1, false, false, 0.05 + 0.8},
        {2, true, true, 0.05 + 0.3 + 0.6 + 0.6 + 0.99},
        {2, true, false, 0.05 + 0.3 + 0.6 + 0.99},
        {2, false, true, 0.05 + 0.3 + 0.6 + 0.99},
        {2, false, false, 0.05 + 0.3 + 0.99},
    };
    for (const Case& c : cases) {
        const Attribute a = manual_attribute(c.attribute);
        const ShadingSettings settings = switches(c.feelers, c.reflection);
        EXPECT_NEAR(intensity_bound(a, settings, kOneWhiteLight), c.bound, 1e-12)
            << "attribute " << c.attribute;
        const double expected = c.bound > 1.0 ? 1.0 / c.bound : 1.0;
        EXPECT_NEAR(weight_scale(a, settings, kOneWhiteLight), expected, 1e-12)
            << "attribute " << c.attribute;
    }
    EXPECT_EQ(weight_scale(manual_attribute(0), switches(false, false), kOneWhiteLight),
              1.0);  // 0.95
}

TEST(WeightScaling, LightsSumAndTheLargestChannelCounts) {
    EXPECT_NEAR(intensity_bound(manual_attribute(0), switches(true, true), {1.5, 2.1, 0.9}),
                0.05 + 2.1 * (0.9 + 0.1) + 0.1, 1e-12);
}

TEST(WeightScaling, AttenuatedFeelersDivideByTheConstant) {
    ShadingSettings settings = switches(true, true);
    settings.attenuation_constant = 2.0;
    EXPECT_NEAR(intensity_bound(manual_attribute(0), settings, kOneWhiteLight),
                0.05 + 0.5 * 1.0 + 0.1, 1e-12);
    EXPECT_EQ(weight_scale(manual_attribute(0), settings, kOneWhiteLight), 1.0);
    settings.attenuate_feelers = false;  // -Dl
    EXPECT_NEAR(intensity_bound(manual_attribute(0), settings, kOneWhiteLight), 1.15, 1e-12);
}

TEST(WeightScaling, TotalLightSumsThePointLights) {
    const std::vector<PointLight> lights = {{{0, 0, 0}, {0.5, 0.5, 0.5}, 0},
                                            {{1, 0, 0}, {0.5, 1.0, 0.25}, 0}};
    EXPECT_EQ(total_light(lights), (Rgb{1.0, 1.5, 0.75}));
    EXPECT_EQ(total_light({}), Rgb{});
}

TEST(WeightScaling, TheAmbientLightScalesTheAmbientWeight) {
    ShadingSettings settings = switches(false, false);
    settings.ambient_light = 0.5;
    EXPECT_NEAR(intensity_bound(manual_attribute(0), settings, kOneWhiteLight), 0.05 * 0.5 + 0.9,
                1e-12);
}

TEST(WeightScaling, ScaledWeightsReachTheBoundOne) {
    const Attribute a = manual_attribute(2);
    const ShadingSettings settings = switches(true, true);
    const Attribute scaled = scale_weights(a, weight_scale(a, settings, kOneWhiteLight));
    EXPECT_NEAR(intensity_bound(scaled, settings, kOneWhiteLight), 1.0, 1e-12);
    EXPECT_NEAR(scaled.transmission, 0.99 / 2.54, 1e-12);
    EXPECT_EQ(scaled.color, a.color);
    EXPECT_EQ(scaled.specular_exponent, a.specular_exponent);
}

}  // namespace
}  // namespace rt
