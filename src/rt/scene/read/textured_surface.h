// Builds a texture-mapped optical surface (-V, manual 2.2) into the Scene: the cells of its grid
// become polygons through the SceneBuilder, and each points at a TextureCell holding the cell's
// tangent frame and its element of the texture map, in world space.
#pragma once

#include <cstdint>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/scene_builder.h"
#include "rt/scene/read/scn_reader.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/scene.h"

namespace rt {

/// Reads the grid (source_files[file]) and the texture map, and adds the surface. Degenerate
/// cells are skipped with a warning; a cell whose corners are not in one plane is an error.
void add_textured_surface(SceneBuilder& builder, Scene& scene, const ScnTexturedSurface& entry,
                          const SourceText& grid_file, const SourceText& texture_map_file,
                          std::uint32_t file, Diagnostics& diagnostics);

/// How far a cell's corners may lie from its plane, as a fraction of its longest diagonal.
inline constexpr double kCellFlatness = 1e-3;

}  // namespace rt
