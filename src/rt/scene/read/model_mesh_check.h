// The clean-up a model file's polygons need before the scene builder takes them (docs/formats.md,
// "Filetype 3"): model formats repeat a vertex for each set of normals or texture coordinates
// it has, so neighbours would not share corners; and they may leave a model open.
#pragma once

#include <string>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/surface_mesh.h"

namespace rt {

/// Joins vertices at exactly the same position, so that neighbouring polygons share corners (and
/// intersection stays watertight), and drops a corner that repeats the one before it (a zero-length
/// edge). A polygon whose loop still passes through one corner twice is skipped with a warning
/// naming `name`. In place: the polygons' loops must lie one after the other in polygon order, as
/// SurfaceMesh::add_polygon lays them out. The vertices' lines are dropped (they no longer match).
void weld_vertices(SurfaceMesh& mesh, const std::string& name, Diagnostics& diagnostics);

/// One warning if some edge borders one polygon only, or more than two: the model is not a closed
/// surface, so its inside and outside are not defined (refraction needs them).
void warn_if_not_watertight(const SurfaceMesh& mesh, const std::string& name,
                            Diagnostics& diagnostics);

}  // namespace rt
