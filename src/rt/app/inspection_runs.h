// What rt does instead of ray tracing: -w draws the wireframe (docs/wireframe.md) and -doi walks
// the octree in a session (docs/accelerators.md). run() calls these after loading the scene.
#pragma once

#include <memory>
#include <string_view>

#include "rt/accel/octree/octree.h"
#include "rt/app/options.h"
#include "rt/app/run.h"
#include "rt/image/film.h"
#include "rt/scene/scene.h"

namespace rt {

/// The octree -oo draws and -doi walks: the one the run's settings build (--accel octree or the
/// scene header's "1 depth", -od, -ol, -ss, -op, -of), built even when the run's method is
/// another (`what` names the switch in the note that says so).
std::unique_ptr<Octree> octree_to_inspect(const Scene& scene, const Options& options,
                                          std::string_view what, const RunConsole& console);

/// -w: the wireframe of the scene (and with -oo, the octree's boxes) in a film of the window.
Film wireframe_picture(const Scene& scene, const Options& options, const PixelRect& window,
                       const RunConsole& console);

/// -doi: the octree session on the console's command and answer streams. Throws UsageError when
/// the console has none.
void inspect_octree(const Scene& scene, const Options& options, const RunConsole& console);

}  // namespace rt
