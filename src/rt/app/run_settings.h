// The library settings a command line asks for, given the loaded scene: what run() uses, shared
// with programs that drive the renderer themselves (bench/scenes).
#pragma once

#include "rt/app/options.h"
#include "rt/app/run.h"
#include "rt/image/film.h"
#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// The shading switches (-A, -D..., -T, -Po) as the shading settings.
ShadingSettings shading_settings(const Options& options);

/// The scene's output matrix, cut at -L. Throws UsageError for an -L above the window.
PixelRect render_window(const Scene& scene, const Options& options);

/// What the switches change in the loaded scene itself: -E's crease normals and -K's scaled
/// weights (which depend on the lights the shading settings keep).
void prepare_scene(Scene& scene, const Options& options, const ShadingSettings& settings);

/// The intersection method comes from AcceleratorStack (rt/app/accelerator_stack.h).

}  // namespace rt
