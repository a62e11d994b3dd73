// Reads an optical surface file of any filetype (manual 2.5) into a SurfaceMesh.
#pragma once

#include "rt/core/diagnostics.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/read/surface_mesh.h"

namespace rt {

/// filetype 0 (polygon file), 1 (Phigs+ subset) or 2 (Prinz polygonizer); with -M only filetype 0
/// carries marks, the others are read with every polygon Ordinary.
SurfaceMesh read_optical_surface(const SourceText& source, int filetype,
                                 const ReaderDialect& dialect, Diagnostics& diagnostics);

}  // namespace rt
