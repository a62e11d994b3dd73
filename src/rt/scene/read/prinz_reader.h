// Optical surface filetype 2, from the polygonizer of Fritz Prinz's group (manual 2.5):
// {solid {face {loop a b c}} {node {position x y z}} ...}. Nodes are numbered by order of
// appearance from 0, faces and nodes come in any order, faces are triangles whose corners run
// counter-clockwise seen from outside.
#pragma once

#include "rt/core/diagnostics.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/read/surface_mesh.h"

namespace rt {

SurfaceMesh read_prinz_file(const SourceText& source, Diagnostics& diagnostics);

}  // namespace rt
