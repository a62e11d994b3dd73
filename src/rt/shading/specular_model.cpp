#include "rt/shading/specular_model.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include "rt/core/error.h"

namespace rt {

namespace {

// s-independent Phong lobe: cos^n of the angle between the mirrored light and the viewer.
double phong_lobe(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer, double exponent) {
    const Vec3 mirrored = n * (2.0 * dot(n, to_light)) - to_light;
    const double cos_alpha = dot(mirrored, to_viewer);
    return cos_alpha > 0.0 ? std::pow(std::min(cos_alpha, 1.0), exponent) : 0.0;
}

bool is_torrance_sparrow(SpecularLaw law) {
    return law == SpecularLaw::TorranceSparrowGaussian ||
           law == SpecularLaw::TorranceSparrowBeckmann;
}

// The law's value without Fresnel, tint or s.
double law_value(const SpecularSettings& settings, const Attribute& attribute, const Vec3& n,
                 const Vec3& to_light, const Vec3& to_viewer) {
    switch (settings.law()) {
        case SpecularLaw::Phong:
            return phong_lobe(n, to_light, to_viewer, attribute.specular_exponent);
        case SpecularLaw::PhongGeometric:
            return phong_lobe(n, to_light, to_viewer, attribute.specular_exponent) *
                   geometric_attenuation(n, to_viewer, to_light);
        case SpecularLaw::TorranceSparrowGaussian:
        case SpecularLaw::TorranceSparrowBeckmann: {
            const double cos_beta = dot(n, normalize(to_light + to_viewer));
            const double m = settings.slope_m();
            const double d =
                settings.law() == SpecularLaw::TorranceSparrowBeckmann
                    ? beckmann_distribution(cos_beta, m)
                    : gaussian_distribution(cos_beta, m, settings.gaussian_normaliser());
            const double g = geometric_attenuation(n, to_viewer, to_light);
            return d * g / (4.0 * dot(n, to_viewer));
        }
    }
    return 0.0;
}

// The shortest text that reads back as `value` ("1e-06", "0.3"), for messages.
std::string shortest(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

}  // namespace

SpecularSettings make_specular_settings(SpecularLaw law, double slope_m, HighlightTint tint) {
    SpecularSettings settings;
    settings.tint = tint;
    settings.law_ = law;
    settings.slope_m_ = slope_m;
    if (is_torrance_sparrow(law)) {
        if (!(slope_m >= kLeastMicrofacetSlope) || !std::isfinite(slope_m)) {
            throw SettingError("microfacet slope m",
                               "the microfacet slope m of Torrance-Sparrow must be finite and at "
                               "least " +
                                   shortest(kLeastMicrofacetSlope) + ", not " + shortest(slope_m));
        }
        settings.gaussian_normaliser_ = gaussian_normaliser(slope_m);
    }
    return settings;
}

Rgb specular_highlight(const SpecularSettings& settings, const Attribute& attribute,
                       const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer) {
    return specular_highlight(settings, attribute, attribute.color, normal, to_light, to_viewer);
}

Rgb specular_highlight(const SpecularSettings& settings, const Attribute& attribute,
                       const Rgb& color, const Vec3& normal, const Vec3& to_light,
                       const Vec3& to_viewer) {
    if (dot(normal, to_light) <= 0.0 || dot(normal, to_viewer) <= 0.0 ||
        attribute.specular == 0.0) {
        return {};
    }
    const double value =
        attribute.specular * law_value(settings, attribute, normal, to_light, to_viewer);
    if (value == 0.0) {
        return {};
    }
    const double cos_vh = dot(to_viewer, normalize(to_light + to_viewer));
    if (settings.tint == HighlightTint::Fresnel) {
        Rgb result;
        for (int c = 0; c < 3; ++c) {
            const double n_c = index_from_reflectance(color[c]);
            result[c] = value * fresnel_dielectric(cos_vh, 1.0, n_c);
        }
        return result;
    }
    const double f = is_torrance_sparrow(settings.law())
                         ? fresnel_dielectric(cos_vh, 1.0, attribute.refraction_index.g)
                         : 1.0;
    const Rgb grey{value * f, value * f, value * f};
    return settings.tint == HighlightTint::ObjectColor ? grey * color : grey;
}

double fresnel_dielectric(double cos_i, double n1, double n2) {
    const double ci = std::min(std::fabs(cos_i), 1.0);
    const double eta = n1 / n2;
    const double sin2_t = eta * eta * (1.0 - ci * ci);
    if (sin2_t >= 1.0) {
        return 1.0;  // total internal reflection
    }
    const double ct = std::sqrt(1.0 - sin2_t);
    const double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
    const double rp = (n1 * ct - n2 * ci) / (n1 * ct + n2 * ci);
    return 0.5 * (rs * rs + rp * rp);
}

double index_from_reflectance(double f0) {
    const double root = std::sqrt(std::clamp(f0, 0.0, 0.9999));
    return (1.0 + root) / (1.0 - root);
}

double gaussian_distribution(double cos_beta, double m, double normaliser) {
    if (cos_beta <= 0.0) {
        return 0.0;
    }
    const double beta = std::acos(std::min(cos_beta, 1.0));
    const double x = beta / m;
    return normaliser * std::exp(-x * x);
}

double gaussian_normaliser(double m) {
    // 2 pi * integral over [0, pi/2] of exp(-(b/m)^2) cos b sin b db by Simpson's rule; beyond
    // b = 8m the integrand is below e^-64 of its scale and is left out.
    const double upper = std::min(std::numbers::pi / 2.0, 8.0 * m);
    constexpr int kIntervals = 4096;  // even
    const double h = upper / kIntervals;
    const auto f = [m](double b) {
        const double x = b / m;
        return std::exp(-x * x) * std::cos(b) * std::sin(b);
    };
    double sum = f(0.0) + f(upper);
    for (int i = 1; i < kIntervals; ++i) {
        sum += f(i * h) * (i % 2 == 1 ? 4.0 : 2.0);
    }
    const double integral = 2.0 * std::numbers::pi * sum * h / 3.0;
    return 1.0 / integral;
}

double beckmann_distribution(double cos_beta, double m) {
    if (cos_beta <= 0.0) {
        return 0.0;
    }
    const double c = std::min(cos_beta, 1.0);
    const double c2 = c * c;
    const double tan2 = (1.0 - c2) / c2;
    return std::exp(-tan2 / (m * m)) / (std::numbers::pi * m * m * c2 * c2);
}

double geometric_attenuation(const Vec3& normal, const Vec3& to_viewer, const Vec3& to_light) {
    const Vec3 sum = to_viewer + to_light;
    const double len = length(sum);
    if (len == 0.0) {
        return 0.0;
    }
    const Vec3 h = sum / len;
    const double vh = dot(to_viewer, h);
    const double nh = dot(normal, h);
    if (vh <= 0.0 || nh <= 0.0) {
        return 0.0;
    }
    const double masking = 2.0 * nh * dot(normal, to_viewer) / vh;
    const double shadowing = 2.0 * nh * dot(normal, to_light) / vh;
    return std::clamp(std::min({1.0, masking, shadowing}), 0.0, 1.0);
}

}  // namespace rt
