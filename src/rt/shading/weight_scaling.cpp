#include "rt/shading/weight_scaling.h"

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

}  // namespace rt
