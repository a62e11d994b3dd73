#include "rt/shading/weight_scaling.h"

#include <vector>

namespace rt {

Rgb total_light(std::span<const PointLight> lights) {
    Rgb sum;
    for (const PointLight& light : lights) {
        sum += light.intensity;
    }
    return sum;
}

double intensity_bound(const Attribute& a, const ShadingSettings& settings,
                       const Rgb& total_light) {
    double light = 0.0;
    if (settings.shadow_feelers) {
        light = max_component(total_light);
        if (settings.attenuate_feelers && settings.attenuation_constant > 0.0) {
            light /= settings.attenuation_constant;
        }
    }
    const double diffuse_in = settings.shadow_feelers ? light : 1.0;
    const double reflected = settings.reflection ? a.specular : 0.0;
    return a.emission + a.ambient * settings.ambient_light + a.diffuse * diffuse_in +
           a.specular * light + reflected + a.transmission;
}

double weight_scale(const Attribute& attribute, const ShadingSettings& settings,
                    const Rgb& total_light) {
    const double bound = intensity_bound(attribute, settings, total_light);
    return bound > 1.0 ? 1.0 / bound : 1.0;
}

Attribute scale_weights(Attribute attribute, double scale) {
    attribute.emission *= scale;
    attribute.ambient *= scale;
    attribute.diffuse *= scale;
    attribute.specular *= scale;
    attribute.transmission *= scale;
    return attribute;
}

void scale_scene_weights(Scene& scene, const ShadingSettings& settings) {
    const std::vector<PointLight> lights =
        settings.shadow_feelers
            ? collect_point_lights(scene, scene.header.lghtick, settings.share_light_among_points)
            : std::vector<PointLight>{};
    const Rgb light = total_light(lights);
    for (Attribute& a : scene.attributes) {
        a = scale_weights(a, weight_scale(a, settings, light));
    }
}

}  // namespace rt
