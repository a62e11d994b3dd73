// The texture-mapped optical surfaces of -V (manual 2.2): after the entities, a count and one line
// per surface: attribute, polygon file, texture map, scale, translation, rotation, rows, columns.
#pragma once

#include "rt/core/diagnostics.h"
#include "rt/scene/read/item_stream.h"
#include "rt/scene/read/scn_reader.h"

namespace rt {

/// Appends every texture-mapped surface to scene.textured_surfaces; lines after the last are
/// ignored with one warning. The lines must be there: a .scn that ends after its entities is
/// "expected the texture-mapped surface count (-V), found end of file".
void read_textured_surfaces(ItemStream& scn, ScnFile& scene, Diagnostics& diagnostics);

}  // namespace rt
