// The entities of a .scn (manual 2.2): a count, then per entity a count of optical surfaces and
// one line per surface; then whatever follows the entities.
#pragma once

#include "rt/core/diagnostics.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/read/item_stream.h"
#include "rt/scene/read/scn_reader.h"

namespace rt {

/// Appends every optical surface of every entity to scene.surfaces.
void read_entities(ItemStream& scn, const ReaderDialect& dialect, ScnFile& scene,
                   Diagnostics& diagnostics);

/// With -V, the texture-mapped surfaces that follow the entities (scn_textures.h); without it,
/// lines left after the entities are ignored with one warning.
void read_after_entities(ItemStream& scn, const ReaderDialect& dialect, ScnFile& scene,
                         Diagnostics& diagnostics);

}  // namespace rt
