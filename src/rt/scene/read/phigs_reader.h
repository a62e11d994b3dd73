// Optical surface filetype 1: a documented text subset of PHIGS PLUS "FILL AREA SET 3 WITH DATA"
// (the manual gives no format; docs/formats.md defines this one). Each record:
//   FILL_AREA_SET_3_WITH_DATA [FACET_NORMAL x y z] [ATTRIBUTE_OFFSET k] BOUNDARY n x y z ... END
// '#' starts a comment; line breaks carry no meaning. Polygons cannot be smooth-shaded or marked.
#pragma once

#include "rt/core/diagnostics.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/read/surface_mesh.h"

namespace rt {

SurfaceMesh read_phigs_file(const SourceText& source, Diagnostics& diagnostics);

}  // namespace rt
