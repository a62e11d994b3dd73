// The specular laws, Fresnel reflectance and highlight tints against numbers worked out by hand.
#include "rt/shading/specular_model.h"

#include <cmath>
#include <numbers>
#include <random>
#include <type_traits>

#include "rt/core/error.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr double kPi = std::numbers::pi;

// Fresnel reflectance in the form of Cook and Torrance (and Rogers), from air onto index n:
// g^2 = n^2 + c^2 - 1, F = (g-c)^2/(2(g+c)^2) [1 + (c(g+c)-1)^2 / (c(g-c)+1)^2].
double cook_torrance_fresnel(double c, double n) {
    const double g = std::sqrt(n * n + c * c - 1.0);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

TEST(Fresnel, MatchesTheCookTorranceFormAtSeveralAngles) {
    for (const double n : {1.05, 1.33, 1.5, 2.4}) {
        for (const double degrees : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0}) {
            const double c = std::cos(degrees * kPi / 180.0);
            EXPECT_NEAR(fresnel_dielectric(c, 1.0, n), cook_torrance_fresnel(c, n), 1e-12)
                << "n " << n << " at " << degrees << " degrees";
        }
    }
}

TEST(Fresnel, NormalIncidenceIsTheSquaredIndexRatio) {
    for (const double n : {1.05, 1.5, 2.0}) {
        const double expected = std::pow((n - 1.0) / (n + 1.0), 2.0);
        EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, n), expected, 1e-15);
        EXPECT_NEAR(fresnel_dielectric(1.0, n, 1.0), expected, 1e-15);  // either way round
    }
    EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.5), 0.04, 1e-15);
    EXPECT_EQ(fresnel_dielectric(0.7, 1.3, 1.3), 0.0);
}

TEST(Fresnel, GrazingIncidenceReflectsEverything) {
    EXPECT_NEAR(fresnel_dielectric(0.0, 1.0, 1.5), 1.0, 1e-12);
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
    // Glass (1.5) to air: critical angle asin(1/1.5) = 41.81 degrees.
    const double critical = std::asin(1.0 / 1.5);
    EXPECT_EQ(fresnel_dielectric(std::cos(critical + 0.01), 1.5, 1.0), 1.0);
    EXPECT_EQ(fresnel_dielectric(std::cos(kPi / 3.0), 1.5, 1.0), 1.0);
    EXPECT_LT(fresnel_dielectric(std::cos(critical - 0.05), 1.5, 1.0), 1.0);
    EXPECT_EQ(fresnel_dielectric(-std::cos(kPi / 3.0), 1.5, 1.0), 1.0);  // sign ignored
}

TEST(Fresnel, IndexFromReflectanceInvertsNormalIncidence) {
    for (const double f0 : {0.0, 0.04, 0.2, 0.5, 0.98}) {
        EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, index_from_reflectance(f0)), f0, 1e-12);
    }
    EXPECT_NEAR(index_from_reflectance(0.04), 1.5, 1e-12);
    EXPECT_TRUE(std::isfinite(index_from_reflectance(1.0)));  // clamped below 1
}

// Integral over the hemisphere of D(h) (n.h) d(omega): the projected solid angle
// (n.h) d(omega) is area on the unit disk, so a midpoint grid over the disk does it.
template <typename D>
double projected_integral(D distribution) {
    constexpr int kGrid = 2000;
    const double h = 2.0 / kGrid;
    double sum = 0.0;
    for (int i = 0; i < kGrid; ++i) {
        const double x = -1.0 + (i + 0.5) * h;
        for (int j = 0; j < kGrid; ++j) {
            const double y = -1.0 + (j + 0.5) * h;
            const double r2 = x * x + y * y;
            if (r2 < 1.0) {
                sum += distribution(std::sqrt(1.0 - r2));
            }
        }
    }
    return sum * h * h;
}

TEST(MicrofacetDistribution, GaussianIsNormalised) {
    for (const double m : {0.1, 0.3, 1.0}) {
        const double c = gaussian_normaliser(m);
        const double integral = projected_integral(
            [&](double cos_beta) { return gaussian_distribution(cos_beta, m, c); });
        EXPECT_NEAR(integral, 1.0, 1e-3) << "m " << m;
    }
}

TEST(MicrofacetDistribution, GaussianNormaliserTendsToOneOverPiMSquared) {
    // For small m the facet angles are small: integral ~ 2 pi int b exp(-b^2/m^2) db = pi m^2.
    const double m = 0.01;
    EXPECT_NEAR(gaussian_normaliser(m) * kPi * m * m, 1.0, 1e-3);
}

// Dawson's integral F(x) = exp(-x^2) int_0^x exp(t^2) dt by its series
// sum (-1)^k 2^k x^(2k+1) / (1 3 5 ... (2k+1)), which converges fast for the |x| < 1 used here.
double dawson(double x) {
    double term = x;
    double sum = x;
    for (int k = 1; k < 60; ++k) {
        term *= -2.0 * x * x / (2 * k + 1);
        sum += term;
    }
    return sum;
}

// The Gaussian's normaliser in closed form: int over the hemisphere of exp(-(b/m)^2) cos b
// d(omega) = pi int_0^(pi/2) exp(-b^2/m^2) sin 2b db, and int_0^inf exp(-a x^2) sin(2x) dx =
// F(sqrt(1/a)) / sqrt(a), so it is pi m F(m), less a tail below exp(-(pi/2m)^2) (1e-12 for
// m = 0.3).
double gaussian_normaliser_closed_form(double m) {
    return 1.0 / (kPi * m * dawson(m));
}

TEST(MicrofacetDistribution, GaussianNormaliserHasAClosedForm) {
    EXPECT_NEAR(dawson(0.5), 0.4244363835020223, 1e-15);  // Abramowitz and Stegun, table 7.5
    for (const double m : {0.05, 0.1, 0.2, 0.3}) {
        const double expected = gaussian_normaliser_closed_form(m);
        EXPECT_NEAR(gaussian_normaliser(m), expected, 1e-9 * expected) << "m " << m;
    }
}

TEST(MicrofacetDistribution, BeckmannIsNormalised) {
    for (const double m : {0.1, 0.3, 1.0}) {
        const double integral =
            projected_integral([&](double cos_beta) { return beckmann_distribution(cos_beta, m); });
        EXPECT_NEAR(integral, 1.0, 1e-3) << "m " << m;
    }
}

TEST(MicrofacetDistribution, PeakValuesAndBelowTheSurface) {
    EXPECT_NEAR(beckmann_distribution(1.0, 0.3), 1.0 / (kPi * 0.09), 1e-12);
    EXPECT_NEAR(gaussian_distribution(1.0, 0.3, 7.0), 7.0, 1e-12);
    EXPECT_NEAR(gaussian_distribution(std::cos(0.3), 0.3, 1.0), std::exp(-1.0), 1e-12);
    EXPECT_EQ(beckmann_distribution(0.0, 0.3), 0.0);
    EXPECT_EQ(gaussian_distribution(-0.5, 0.3, 1.0), 0.0);
}

constexpr Vec3 kNormal{0.0, 0.0, 1.0};

Vec3 at_angle(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(GeometricAttenuation, OneAtNormalIncidence) {
    EXPECT_DOUBLE_EQ(geometric_attenuation(kNormal, kNormal, kNormal), 1.0);
}

TEST(GeometricAttenuation, NeverAboveOneNorBelowZero) {
    std::mt19937 engine(12345);
    std::uniform_real_distribution<double> theta(0.0, kPi / 2.0);
    std::uniform_real_distribution<double> phi(0.0, 2.0 * kPi);
    for (int i = 0; i < 10000; ++i) {
        const double g = geometric_attenuation(kNormal, at_angle(theta(engine), phi(engine)),
                                               at_angle(theta(engine), phi(engine)));
        ASSERT_GE(g, 0.0);
        ASSERT_LE(g, 1.0);
    }
}

constexpr double kDegree = kPi / 180.0;

TEST(GeometricAttenuation, GrazingMirrorConfigurationIsMasked) {
    // V and L both 80 degrees from N, opposite azimuths: H = N, V.H = cos 80,
    // 2 (N.H)(N.V)/(V.H) = 2: no masking. Same azimuth, V at 80, L at 10: H halfway, 45 degrees
    // from N and 35 from each; masking 2 cos 45 cos 80 / cos 35 = 0.2998, shadowing 1.70.
    EXPECT_DOUBLE_EQ(geometric_attenuation(kNormal, at_angle(1.396, 0.0), at_angle(1.396, kPi)),
                     1.0);
    const Vec3 v = at_angle(80 * kDegree, 0.0);
    const Vec3 l = at_angle(10 * kDegree, 0.0);
    const double masking =
        2 * std::cos(45 * kDegree) * std::cos(80 * kDegree) / std::cos(35 * kDegree);
    EXPECT_NEAR(masking, 0.29979, 1e-5);
    EXPECT_NEAR(geometric_attenuation(kNormal, v, l), masking, 1e-12);
}

Attribute shiny() {
    Attribute a;
    a.color = {0.8, 0.2, 0.05};
    a.specular = 0.6;
    a.specular_exponent = 10.0;
    a.refraction_index = {1.5, 1.5, 1.5};
    return a;
}

TEST(SpecularHighlight, PhongAtTheMirrorDirectionIsTheSpecularWeight) {
    const Attribute a = shiny();
    const Vec3 l = at_angle(0.5, 0.0);
    const Vec3 v = at_angle(0.5, kPi);
    const Rgb h = specular_highlight({}, a, kNormal, l, v);
    EXPECT_NEAR(h.r, 0.6, 1e-12);
    EXPECT_NEAR(h.g, 0.6, 1e-12);
    EXPECT_NEAR(h.b, 0.6, 1e-12);
}

TEST(SpecularHighlight, PhongFollowsCosToThePow) {
    const Attribute a = shiny();
    const Vec3 l = kNormal;
    const Vec3 v = at_angle(0.3, 1.0);  // mirrored light is N: alpha = 0.3
    EXPECT_NEAR(specular_highlight({}, a, kNormal, l, v).g, 0.6 * std::pow(std::cos(0.3), 10.0),
                1e-12);
}

TEST(SpecularHighlight, NothingWhenLightOrViewerIsBelow) {
    const Attribute a = shiny();
    const Vec3 below = at_angle(2.0, 0.0);
    for (const SpecularLaw law :
         {SpecularLaw::Phong, SpecularLaw::PhongGeometric, SpecularLaw::TorranceSparrowGaussian,
          SpecularLaw::TorranceSparrowBeckmann}) {
        const SpecularSettings s = make_specular_settings(law, 0.3, HighlightTint::LightColor);
        EXPECT_EQ(specular_highlight(s, a, kNormal, below, kNormal), Rgb{});
        EXPECT_EQ(specular_highlight(s, a, kNormal, kNormal, below), Rgb{});
    }
}

TEST(SpecularHighlight, PhongGeometricIsPhongTimesG) {
    // L 1.0 rad from N, V 1.45 rad on the other side, in one plane. The mirrored light is 0.45
    // from V; H lies (1.45 - 1.0) / 2 = 0.225 from N and 2.45 / 2 = 1.225 from V and from L, so
    // G = min(1, 2 cos 0.225 cos 1.45 / cos 1.225, 2 cos 0.225 cos 1.0 / cos 1.225) = 0.6931
    // (masked: the first term).
    const Attribute a = shiny();
    const Vec3 l = at_angle(1.0, 0.0);
    const Vec3 v = at_angle(1.45, kPi);
    const SpecularSettings sg =
        make_specular_settings(SpecularLaw::PhongGeometric, 1.0, HighlightTint::LightColor);
    const double phong = 0.6 * std::pow(std::cos(0.45), 10.0);
    const double g = 2 * std::cos(0.225) * std::cos(1.45) / std::cos(1.225);
    EXPECT_NEAR(g, 0.69312, 1e-5);
    EXPECT_NEAR(specular_highlight({}, a, kNormal, l, v).g, phong, 1e-12);
    EXPECT_NEAR(specular_highlight(sg, a, kNormal, l, v).g, phong * g, 1e-12);
    EXPECT_NEAR(specular_highlight(sg, a, kNormal, kNormal, kNormal).g, 0.6, 1e-12);
}

TEST(SpecularHighlight, TorranceSparrowAtNormalIncidence) {
    // L = V = N: H = N, G = 1, N.V = 1, F = ((n-1)/(n+1))^2 = 0.04 for n = 1.5, D at its peak:
    // 1 / (pi m^2) for Beckmann, the normaliser for the Gaussian.
    const Attribute a = shiny();
    const double m = 0.3;
    const SpecularSettings beckmann =
        make_specular_settings(SpecularLaw::TorranceSparrowBeckmann, m, HighlightTint::LightColor);
    EXPECT_NEAR(specular_highlight(beckmann, a, kNormal, kNormal, kNormal).r,
                0.6 * 0.04 / (kPi * m * m) / 4.0, 1e-12);
    const double expected = 0.6 * 0.04 * gaussian_normaliser_closed_form(m) / 4.0;
    const SpecularSettings gaussian =
        make_specular_settings(SpecularLaw::TorranceSparrowGaussian, m, HighlightTint::LightColor);
    EXPECT_NEAR(specular_highlight(gaussian, a, kNormal, kNormal, kNormal).b, expected,
                1e-9 * expected);
}

TEST(SpecularHighlight, TorranceSparrowUsesTheGreenIndex) {
    Attribute a = shiny();
    a.refraction_index = {1.2, 2.0, 3.0};
    const SpecularSettings s = make_specular_settings(SpecularLaw::TorranceSparrowBeckmann, 0.5,
                                                      HighlightTint::LightColor);
    const double f = 1.0 / 9.0;  // ((2-1)/(2+1))^2
    EXPECT_NEAR(specular_highlight(s, a, kNormal, kNormal, kNormal).r, 0.6 * f / (kPi * 0.25) / 4.0,
                1e-12);
}

TEST(SpecularHighlight, ObjectColorFiltersTheHighlight) {
    // The mirrored light is 0.5 from N opposite L, so 0.1 from V: s cos^10(0.1) times the colour.
    const Attribute a = shiny();
    const Vec3 l = at_angle(0.5, 0.0);
    const Vec3 v = at_angle(0.4, kPi);
    const SpecularSettings co =
        make_specular_settings(SpecularLaw::Phong, 1.0, HighlightTint::ObjectColor);
    const double grey = 0.6 * std::pow(std::cos(0.1), 10.0);
    const Rgb tinted = specular_highlight(co, a, kNormal, l, v);
    EXPECT_NEAR(tinted.r, grey * 0.8, 1e-12);
    EXPECT_NEAR(tinted.g, grey * 0.2, 1e-12);
    EXPECT_NEAR(tinted.b, grey * 0.05, 1e-12);
}

TEST(SpecularHighlight, FresnelTintDiffersByChannel) {
    const Attribute a = shiny();
    const SpecularSettings cf =
        make_specular_settings(SpecularLaw::Phong, 1.0, HighlightTint::Fresnel);
    // At normal incidence each channel's reflectance is the colour itself.
    const Rgb normal = specular_highlight(cf, a, kNormal, kNormal, kNormal);
    EXPECT_NEAR(normal.r, 0.6 * 0.8, 1e-12);
    EXPECT_NEAR(normal.g, 0.6 * 0.2, 1e-12);
    EXPECT_NEAR(normal.b, 0.6 * 0.05, 1e-12);
    // Toward grazing every channel whitens, the dark ones the most.
    const Vec3 l = at_angle(1.4, 0.0);
    const Vec3 v = at_angle(1.4, kPi);
    const Rgb grazing = specular_highlight(cf, a, kNormal, l, v);
    // V.H at the mirror direction is cos 1.4; each channel's index is the one whose reflectance
    // at normal incidence, ((n-1)/(n+1))^2, is the colour: n = (1 + sqrt f0) / (1 - sqrt f0).
    const double c = std::cos(1.4);
    const auto index = [](double f0) { return (1 + std::sqrt(f0)) / (1 - std::sqrt(f0)); };
    EXPECT_NEAR(grazing.r, 0.6 * cook_torrance_fresnel(c, index(0.8)), 1e-12);
    EXPECT_NEAR(grazing.g, 0.6 * cook_torrance_fresnel(c, index(0.2)), 1e-12);
    EXPECT_NEAR(grazing.b, 0.6 * cook_torrance_fresnel(c, index(0.05)), 1e-12);
    EXPECT_GT(grazing.r, grazing.g);
    EXPECT_GT(grazing.g, grazing.b);
    EXPECT_GT(grazing.b / normal.b, grazing.r / normal.r);
}

TEST(SpecularHighlight, FresnelTintReplacesTheScalarFresnelTerm) {
    const Attribute a = shiny();
    const SpecularSettings cf =
        make_specular_settings(SpecularLaw::TorranceSparrowBeckmann, 0.3, HighlightTint::Fresnel);
    const Rgb h = specular_highlight(cf, a, kNormal, kNormal, kNormal);
    const double dg = 1.0 / (kPi * 0.09) / 4.0;
    EXPECT_NEAR(h.r, 0.6 * 0.8 * dg, 1e-12);
    EXPECT_NEAR(h.b, 0.6 * 0.05 * dg, 1e-12);
}

// The normaliser is computed with the law, once: a Gaussian law never goes without it.
TEST(SpecularSettings, AGaussianLawCarriesItsNormaliser) {
    EXPECT_EQ(SpecularSettings{}.law(), SpecularLaw::Phong);
    for (const double m : {0.05, 0.3, 2.0}) {
        const SpecularSettings s =
            make_specular_settings(SpecularLaw::TorranceSparrowGaussian, m, HighlightTint::Fresnel);
        EXPECT_EQ(s.law(), SpecularLaw::TorranceSparrowGaussian);
        EXPECT_EQ(s.slope_m(), m);
        EXPECT_EQ(s.tint, HighlightTint::Fresnel);
        EXPECT_EQ(s.gaussian_normaliser(), gaussian_normaliser(m));
    }
    static_assert(!std::is_aggregate_v<SpecularSettings>,
                  "the law is set only with its normaliser");
}

TEST(SpecularSettings, SlopeMustBePositiveForTorranceSparrow) {
    EXPECT_THROW(make_specular_settings(SpecularLaw::TorranceSparrowGaussian, 0.0,
                                        HighlightTint::LightColor),
                 UsageError);
    EXPECT_THROW(make_specular_settings(SpecularLaw::TorranceSparrowBeckmann, -1.0,
                                        HighlightTint::LightColor),
                 UsageError);
    EXPECT_NO_THROW(make_specular_settings(SpecularLaw::Phong, 0.0, HighlightTint::LightColor));
}

// Every slope the laws accept gives a finite highlight, up to the narrowest: below it the
// formulas overflow (1e-200 used to give NaN pixels), so it is refused.
TEST(SpecularSettings, EveryAcceptedSlopeGivesAFiniteHighlight) {
    const Vec3 normal{0, 0, 1};
    const Vec3 to_light = normalize(Vec3{0.2, 0, 1});
    const Vec3 to_viewer = normalize(Vec3{-0.2, 0, 1});
    Attribute attribute;
    attribute.specular = 1.0;
    for (const SpecularLaw law :
         {SpecularLaw::TorranceSparrowGaussian, SpecularLaw::TorranceSparrowBeckmann}) {
        for (const double m : {kLeastMicrofacetSlope, 1e-3, 1.0, 1e200}) {
            const SpecularSettings s = make_specular_settings(law, m, HighlightTint::LightColor);
            const Rgb head_on = specular_highlight(s, attribute, normal, to_light, to_viewer);
            EXPECT_TRUE(std::isfinite(head_on.r)) << "m = " << m;
        }
        try {
            (void)make_specular_settings(law, 1e-200, HighlightTint::LightColor);
            FAIL() << "a slope below the least was accepted";
        } catch (const SettingError& error) {
            EXPECT_EQ(error.setting(), "microfacet slope m");
            EXPECT_STREQ(error.what(),
                         "the microfacet slope m of Torrance-Sparrow must be finite and at least "
                         "1e-06, not 1e-200");
        }
    }
}

}  // namespace
}  // namespace rt
