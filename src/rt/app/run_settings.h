// What a run derives from the command line and the loaded scene together: the shading settings
// with -Oi/-O1 applied, and the switches' changes to the scene itself (-E, -K). Shared with
// programs that drive the renderer themselves (bench/).
#pragma once

#include "rt/app/options.h"
#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// The shading settings as the switches wrote them, with -Oi's or -O1's model over them.
ShadingSettings run_shading(const Options& options);

/// What the switches change in the loaded scene: -E's crease normals and -K's scaled weights
/// (which depend on the lights the shading settings keep).
void prepare_scene(Scene& scene, const Options& options, const ShadingSettings& shading);

}  // namespace rt
