// The library settings a command line asks for, given the loaded scene: what run() uses, shared
// with programs that drive the renderer themselves (bench/scenes).
#pragma once

#include <memory>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"
#include "rt/app/options.h"
#include "rt/app/run.h"
#include "rt/image/film.h"
#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// The shading switches (-A, -D..., -T, -Po) as the shading settings.
ShadingSettings shading_settings(const Options& options);

/// The scene's output matrix, cut at -L. Throws UsageError for an -L above the window.
FilmWindow render_window(const Scene& scene, const Options& options);

/// The intersection method: the scene header's (manual 2.2), unless --accel names another; -od,
/// -ol, -ss, -op, -on, -of and -tv as given. Throws UsageError for an unknown --accel name.
AccelSettings accel_settings(const Scene& scene, const Options& options);

/// The accelerator accel_settings() names. One the scene header asks for but this build lacks
/// falls back to brute force (same picture) with a note; one asked for by --accel is refused.
std::unique_ptr<Accelerator> build_accelerator(const Scene& scene, const Options& options,
                                               const RunConsole& console);

}  // namespace rt
