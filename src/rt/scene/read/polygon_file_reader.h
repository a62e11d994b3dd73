// Optical surface filetype 0 (manual 2.5): a free-form stream of numbers: vertices (index x y z),
// edges (index v1 v2), polygons (index, n, n edge indices, outward normal x y z, attribute offset,
// and with -M a mark and a shape index). Index numbers are identifiers matched by value.
#pragma once

#include "rt/core/diagnostics.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/read/surface_mesh.h"

namespace rt {

SurfaceMesh read_polygon_file(const SourceText& source, bool marks, Diagnostics& diagnostics);

}  // namespace rt
