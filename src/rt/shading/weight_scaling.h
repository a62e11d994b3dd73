// -K (manual Appendix): "scale down ka, ks, etc. so that intensity need not be clipped (looks at
// -Dr and -Ds switches)". One factor per attribute multiplies all five weights e a d s t.
//
// The bound on the intensity leaving a surface (any channel), when every ray arriving at it
// brings at most 1 in every channel and colours are at most 1:
//
//   bound = e + a*A + d*D + s*L + s' + t
//
//   A  = the ambient light (1 in this release)
//   L  = with shadow feelers: max over channels of the sum of all point lights' intensities,
//        divided by the attenuation constant c when feelers are attenuated (-A d,c: the factor
//        1/(dist/d + c) is at most 1/c); 0 without shadow feelers (-Ds)
//   D  = L with shadow feelers (diffuse light comes only through them); 1 with -Ds (diffusely
//        reflected rays bring back at most 1)
//   s' = s, for the specularly reflected ray, unless reflection is off (-Dr): then 0
//   t  = the transmitted ray
//
// and the scale is 1/bound when bound > 1, else 1. The specular term s*L is a true bound for
// the Phong laws (-Sp -Sg: cos^n <= 1, G <= 1); the Torrance-Sparrow laws can exceed it.
#pragma once

#include <span>

#include "rt/core/rgb.h"
#include "rt/scene/attribute.h"
#include "rt/scene/scene.h"
#include "rt/shading/lights.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// L's sum before the maximum over channels: the sum of all point lights' intensities.
Rgb total_light(std::span<const PointLight> lights);

/// The bound above on the outgoing intensity of a surface with this attribute, under the settings
/// (-Ds, -Dr, -Dl, c of -A, the ambient light) and the lights' `total_light`.
double intensity_bound(const Attribute& attribute, const ShadingSettings& settings,
                       const Rgb& total_light);

/// 1 / intensity_bound when it exceeds 1, else 1: the factor (<= 1) for e, a, d, s and t.
double weight_scale(const Attribute& attribute, const ShadingSettings& settings,
                    const Rgb& total_light);

/// The attribute with e, a, d, s and t multiplied by `scale`.
Attribute scale_weights(Attribute attribute, double scale);

/// -K: every attribute of the scene scaled by its weight_scale, for the point lights the settings
/// give the scene (none without shadow feelers), before anything reads the attributes.
void scale_scene_weights(Scene& scene, const ShadingSettings& settings);

}  // namespace rt
