// What a run derives from the command line and the loaded scene together: the shading settings
// with -Oi/-O1 applied, the intersection method's settings with --threads, and the switches'
// changes to the scene itself (-E, -K). Shared with
// programs that drive the renderer themselves (bench/).
#pragma once

#include "rt/app/options.h"
#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// The shading settings as the switches wrote them, with -Oi's or -O1's model over them.
ShadingSettings run_shading(const Options& options);

/// The intersection method and its layers as the switches wrote them, built on --threads'
/// threads (which the render uses too).
AcceleratorStackSettings run_accelerator_stack(const Options& options);

/// What the switches change in the loaded scene: -E's crease normals and -K's scaled weights
/// (which depend on the lights the shading settings keep).
void prepare_scene(Scene& scene, const Options& options, const ShadingSettings& shading);

}  // namespace rt
