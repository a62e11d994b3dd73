// The specular highlight laws of the manual's -S switches (-Sp -Sg -Stg m -Stb m) and the highlight
// colours of its -C switches (-Ci -Co -Cf). Pure functions; docs/illumination-models.md has the
// formulas.
#pragma once

#include "rt/core/rgb.h"
#include "rt/core/vec3.h"
#include "rt/scene/attribute.h"

namespace rt {

/// The specular reflection law (manual Appendix -S; references [1]-[5]).
enum class SpecularLaw {
    Phong,                    ///< -Sp (default): s cos^pow(alpha)
    PhongGeometric,           ///< -Sg: Phong times the geometric attenuation G
    TorranceSparrowGaussian,  ///< -Stg m: s F D G / (4 N.V), D Gaussian in the facet angle
    TorranceSparrowBeckmann,  ///< -Stb m: the same with Beckmann's D
};

/// The colour of specular highlights (manual Appendix -C).
enum class HighlightTint {
    LightColor,   ///< default and -Ci: the colour of the incident light
    ObjectColor,  ///< -Co: the light filtered through the attribute's colour
    Fresnel,      ///< -Cf: a Fresnel reflectance per RGB channel, the colour taken as F0
};

/// The smallest microfacet slope m the Torrance-Sparrow laws take. Below about 1e-77 the
/// Beckmann law's m^4 and below about 1e-154 the Gaussian normaliser overflow, and a picture of
/// NaNs would follow; a highlight of slope 1e-6 is already far narrower than any sample spacing.
inline constexpr double kLeastMicrofacetSlope = 1e-6;

/// The highlight's law and colour. The law, its slope m and the Gaussian normaliser that follows
/// from m are set together, by make_specular_settings only, so a Gaussian law always carries its
/// normaliser: there is no "not computed yet" state for specular_highlight to detect and repair
/// by redoing the quadrature on every call.
class SpecularSettings {
public:
    HighlightTint tint = HighlightTint::LightColor;  ///< -C, chosen apart from the law

    SpecularLaw law() const { return law_; }
    /// m, the rms slope of the microfacets; the Torrance-Sparrow laws require it finite and at
    /// least kLeastMicrofacetSlope, the Phong laws ignore it.
    double slope_m() const { return slope_m_; }
    /// The constant making the Gaussian distribution a distribution of facet normals for slope_m
    /// (gaussian_normaliser(m)); 0 under the Phong laws, which have no m.
    double gaussian_normaliser() const { return gaussian_normaliser_; }

private:
    friend SpecularSettings make_specular_settings(SpecularLaw law, double slope_m,
                                                   HighlightTint tint);
    SpecularLaw law_ = SpecularLaw::Phong;
    double slope_m_ = 1.0;
    double gaussian_normaliser_ = 0.0;
};

/// Settings for `law` with the Gaussian normaliser computed for `slope_m`. Throws
/// rt::SettingError when a Torrance-Sparrow law is given a slope m below kLeastMicrofacetSlope or
/// not finite.
SpecularSettings make_specular_settings(SpecularLaw law, double slope_m, HighlightTint tint);

/// The factor (per channel) by which the intensity a light delivers at the point is multiplied to
/// give its specular highlight toward the viewer, the attribute's specular weight s included.
/// All vectors are unit; `normal` is on the viewer's side. 0 when the light or the viewer is not
/// above the surface (N.L <= 0 or N.V <= 0).
Rgb specular_highlight(const SpecularSettings& settings, const Attribute& attribute,
                       const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer);
/// The same for a surface whose colour is not its attribute's (a texture map, -V): `color`
/// stands for the attribute's colour in -Co and -Cf.
Rgb specular_highlight(const SpecularSettings& settings, const Attribute& attribute,
                       const Rgb& color, const Vec3& normal, const Vec3& to_light,
                       const Vec3& to_viewer);

/// Unpolarised Fresnel reflectance of a smooth dielectric boundary for light arriving from index
/// n1 onto index n2 at an angle of incidence with cosine cos_i (its absolute value is used):
/// (r_s^2 + r_p^2) / 2, and 1 under total internal reflection.
double fresnel_dielectric(double cos_i, double n1, double n2);

/// The index of refraction whose normal-incidence reflectance from air is f0:
/// (1 + sqrt f0) / (1 - sqrt f0), f0 clamped to [0, 0.9999].
double index_from_reflectance(double f0);

/// The Gaussian facet distribution normaliser * exp(-(beta/m)^2), beta = acos(cos_beta); 0 for
/// cos_beta <= 0.
double gaussian_distribution(double cos_beta, double m, double normaliser);

/// The constant c with integral over the hemisphere of c exp(-(beta/m)^2) cos(beta) d(omega) = 1,
/// by numerical quadrature (m > 0).
double gaussian_normaliser(double m);

/// Beckmann's facet distribution exp(-tan^2(beta)/m^2) / (pi m^2 cos^4(beta)); 0 for
/// cos_beta <= 0. Normalised: its integral of D cos(beta) over the hemisphere is 1.
double beckmann_distribution(double cos_beta, double m);

/// The Torrance-Sparrow (Blinn) geometric attenuation of facets masking and shadowing each other,
/// H = normalize(V + L): min(1, 2 (N.H)(N.V) / (V.H), 2 (N.H)(N.L) / (V.H)), clamped to [0, 1].
double geometric_attenuation(const Vec3& normal, const Vec3& to_viewer, const Vec3& to_light);

}  // namespace rt
