#include "rt/shading/weight_scaling.h"

#include <vector>

namespace rt {

WeightScalingInputs weight_scaling_inputs(const ShadingSettings& settings,
                                          std::span<const PointLight> lights) {
    WeightScalingInputs inputs;
    for (const PointLight& light : lights) {
        inputs.total_light += light.intensity;
    }
    inputs.shadow_feelers = settings.shadow_feelers;
    inputs.reflection = settings.reflection;
    inputs.attenuate_feelers = settings.attenuate_feelers;
    inputs.attenuation_constant = settings.attenuation_constant;
    inputs.ambient_light = settings.ambient_light;
    return inputs;
}

double intensity_bound(const Attribute& a, const WeightScalingInputs& inputs) {
    double light = 0.0;
    if (inputs.shadow_feelers) {
        light = max_component(inputs.total_light);
        if (inputs.attenuate_feelers && inputs.attenuation_constant > 0.0) {
            light /= inputs.attenuation_constant;
        }
    }
    const double diffuse_in = inputs.shadow_feelers ? light : 1.0;
    const double reflected = inputs.reflection ? a.specular : 0.0;
    return a.emission + a.ambient * inputs.ambient_light + a.diffuse * diffuse_in +
           a.specular * light + reflected + a.transmission;
}

double weight_scale(const Attribute& attribute, const WeightScalingInputs& inputs) {
    const double bound = intensity_bound(attribute, inputs);
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
    const WeightScalingInputs inputs = weight_scaling_inputs(settings, lights);
    for (Attribute& a : scene.attributes) {
        a = scale_weights(a, weight_scale(a, inputs));
    }
}

}  // namespace rt
