#include "rt/app/run_settings.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/scene/crease_normals.h"
#include "rt/shading/lights.h"
#include "rt/shading/weight_scaling.h"

namespace rt {

namespace {

SpecularSettings specular_settings(const Options& o) {
    SpecularLaw law = SpecularLaw::Phong;
    switch (o.specular) {
        case SpecularModel::Phong:
            law = SpecularLaw::Phong;
            break;
        case SpecularModel::PhongGeometric:
            law = SpecularLaw::PhongGeometric;
            break;
        case SpecularModel::TorranceSparrowGaussian:
            law = SpecularLaw::TorranceSparrowGaussian;
            break;
        case SpecularModel::TorranceSparrowBeckmann:
            law = SpecularLaw::TorranceSparrowBeckmann;
            break;
    }
    HighlightTint tint = HighlightTint::LightColor;  // the default and -Ci
    if (o.highlight == HighlightColor::ObjectAttenuates) {
        tint = HighlightTint::ObjectColor;
    } else if (o.highlight == HighlightColor::Fresnel) {
        tint = HighlightTint::Fresnel;
    }
    return make_specular_settings(law, o.microfacet_slope, tint);
}

WarnSettings warn_settings(const Options& o) {
    switch (o.warn) {
        case WarnLight::Rogers:
            return {WarnMode::Rogers, 0.0, 0.0};
        case WarnLight::Conical:
            return {WarnMode::Conical, o.warn_parameter, 0.0};
        case WarnLight::Thibadeau:
            return {WarnMode::Thibadeau, 0.0, o.warn_parameter};
        case WarnLight::None:
            break;
    }
    return {};
}

// -K: every attribute's weights scaled down so that intensities need not be clipped
// (docs/illumination-models.md), before anything reads them.
void scale_weights_down(Scene& scene, const ShadingSettings& settings) {
    const std::vector<PointLight> lights =
        settings.shadow_feelers
            ? collect_point_lights(scene, scene.header.lghtick, settings.share_light_among_points)
            : std::vector<PointLight>{};
    const WeightScalingInputs inputs = weight_scaling_inputs(settings, lights);
    for (Attribute& a : scene.attributes) {
        a = scale_weights(a, weight_scale(a, inputs));
    }
}

// -Oi: the earliest version's illumination (docs/rendering.md): Whitted's model as first
// written, before attenuation, transparent shadows and distribution were added, and with the
// lights not yet shared among their point sources.
void apply_early_model(ShadingSettings& s) {
    s.attenuate_rays = false;
    s.attenuate_feelers = false;
    s.feelers_stop_at_transparent = true;
    s.far_side_feelers = false;
    s.share_light_among_points = false;
    s.sampling.distribute = false;
    s.fuzzy = {};
}

}  // namespace

ShadingSettings shading_settings(const Options& o) {
    ShadingSettings s;
    s.attenuation_distance = o.attenuation_distance;
    s.attenuation_constant = o.attenuation_constant;
    s.attenuate_rays = !o.disable_attenuation;
    s.attenuate_feelers = !o.disable_light_attenuation;
    s.shadow_feelers = !o.disable_shadow_feelers;
    s.feelers_stop_at_transparent = o.feelers_stop_at_transparent;
    s.reflection = !o.disable_reflection;
    s.both_sides_emit = !o.single_sided_emitters;
    s.far_side_feelers = o.specular_refraction_feelers;
    s.smooth_shaded_opaque = o.phong == PhongShading::Opaque;
    if (o.fuzzy_distangle) {
        s.fuzzy.angle = *o.fuzzy_distangle;
        s.fuzzy.count = std::max(1, static_cast<int>(std::ceil(o.fuzzy_distfac)));
    }
    SamplingSettings& sampling = s.sampling;
    sampling.seed = o.seed;
    sampling.distribute = !o.disable_distribution;
    sampling.adaptive = !o.disable_adaptive;
    sampling.illuminate_distributed = o.illuminate_distributed;
    if (o.pixel_stop_probability) {
        sampling.pixel_stop = {*o.pixel_stop_probability, o.pixel_stop_variance};
    }
    if (o.ray_stop_probability) {
        sampling.ray_stop = {*o.ray_stop_probability, o.ray_stop_variance};
    }
    s.correct_smoothing = !o.old_intersection_test;
    s.specular = specular_settings(o);
    s.warn = warn_settings(o);
    if (o.old_illumination || o.old_version) {
        apply_early_model(s);
    }
    if (o.old_version) {
        s.sampling.adaptive = false;  // the first version took every sample
    }
    return s;
}

// The output matrix, cut at -L: "draws only from line L up" (row 0 is the top row).
PixelRect render_window(const Scene& scene, const Options& o) {
    PixelRect window = scene.view.window;
    if (o.start_line) {
        if (*o.start_line < window.top) {
            throw UsageError("-L" + std::to_string(*o.start_line) + ": line " +
                             std::to_string(*o.start_line) + " is above the window's top row " +
                             std::to_string(window.top));
        }
        window.bottom = std::min(window.bottom, *o.start_line);
    }
    return window;
}

void prepare_scene(Scene& scene, const Options& options, const ShadingSettings& settings) {
    if (options.crease_angle) {
        compute_crease_normals(scene, *options.crease_angle);
    }
    if (options.scale_weights) {
        scale_weights_down(scene, settings);
    }
}

}  // namespace rt
