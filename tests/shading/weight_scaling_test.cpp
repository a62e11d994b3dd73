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

WeightScalingInputs one_white_light(bool feelers, bool reflection) {
    WeightScalingInputs in;
    in.total_light = {1.0, 0.9, 0.8};
    in.shadow_feelers = feelers;
    in.reflection = reflection;
    return in;
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
        const WeightScalingInputs in = one_white_light(c.feelers, c.reflection);
        EXPECT_NEAR(intensity_bound(a, in), c.bound, 1e-12) << "attribute " << c.attribute;
        const double expected = c.bound > 1.0 ? 1.0 / c.bound : 1.0;
        EXPECT_NEAR(weight_scale(a, in), expected, 1e-12) << "attribute " << c.attribute;
    }
    EXPECT_EQ(weight_scale(manual_attribute(0), one_white_light(false, false)), 1.0);  // 0.95
}

TEST(WeightScaling, LightsSumAndTheLargestChannelCounts) {
    WeightScalingInputs in = one_white_light(true, true);
    in.total_light = {1.5, 2.1, 0.9};
    EXPECT_NEAR(intensity_bound(manual_attribute(0), in), 0.05 + 2.1 * (0.9 + 0.1) + 0.1, 1e-12);
}

TEST(WeightScaling, AttenuatedFeelersDivideByTheConstant) {
    WeightScalingInputs in = one_white_light(true, true);
    in.attenuation_constant = 2.0;
    EXPECT_NEAR(intensity_bound(manual_attribute(0), in), 0.05 + 0.5 * 1.0 + 0.1, 1e-12);
    EXPECT_EQ(weight_scale(manual_attribute(0), in), 1.0);
    in.attenuate_feelers = false;  // -Dl
    EXPECT_NEAR(intensity_bound(manual_attribute(0), in), 1.15, 1e-12);
}

TEST(WeightScaling, InputsFromSettingsAndLights) {
    ShadingSettings settings;
    settings.attenuation_constant = 4.0;
    settings.reflection = false;
    const std::vector<PointLight> lights = {{{0, 0, 0}, {0.5, 0.5, 0.5}, 0},
                                            {{1, 0, 0}, {0.5, 1.0, 0.25}, 0}};
    const WeightScalingInputs in = weight_scaling_inputs(settings, lights);
    EXPECT_EQ(in.total_light, (Rgb{1.0, 1.5, 0.75}));
    EXPECT_TRUE(in.shadow_feelers);
    EXPECT_FALSE(in.reflection);
    EXPECT_TRUE(in.attenuate_feelers);
    EXPECT_EQ(in.attenuation_constant, 4.0);
    EXPECT_EQ(in.ambient_light, 1.0);
}

TEST(WeightScaling, ScaledWeightsReachTheBoundOne) {
    const Attribute a = manual_attribute(2);
    const WeightScalingInputs in = one_white_light(true, true);
    const Attribute scaled = scale_weights(a, weight_scale(a, in));
    EXPECT_NEAR(intensity_bound(scaled, in), 1.0, 1e-12);
    EXPECT_NEAR(scaled.transmission, 0.99 / 2.54, 1e-12);
    EXPECT_EQ(scaled.color, a.color);
    EXPECT_EQ(scaled.specular_exponent, a.specular_exponent);
}

}  // namespace
}  // namespace rt
