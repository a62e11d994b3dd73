// Builds a texture-mapped optical surface (-V, manual 2.2) into the Scene: the cells of its grid
// become polygons through the SceneBuilder, and each points at a TextureCell holding the cell's
// tangent frame and its element of the texture map, in world space.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/scene_builder.h"
#include "rt/scene/read/scn_reader.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/scene.h"

namespace rt {

/// A texture picture the scene holds, or is about to decode: its size from its header.
struct TexturePicture {
    std::string name;      ///< as the texture map names it
    SourceLocation where;  ///< the texture map's line naming it
    int width = 0;
    int height = 0;
    std::uint64_t bytes = 0;  ///< decoded: three a pixel
};

/// Called before a texture picture is decoded, with every picture the scene will then hold (the
/// new one last); throws to refuse it. Empty: no check.
using PictureCheck = std::function<void(const std::vector<TexturePicture>&)>;

/// The texture pictures of one scene load: each file (by its path) is decoded once, after the
/// check has seen its header.
struct TexturePictures {
    PictureCheck check;
    std::vector<TexturePicture> held;
    std::map<std::string, std::int32_t> index;  ///< path -> Scene::texture_images
};

/// Reads the grid (source_files[file]) and the texture map, and adds the surface. Degenerate
/// cells are skipped with a warning; a cell whose corners are not in one plane is an error.
void add_textured_surface(SceneBuilder& builder, Scene& scene, const ScnTexturedSurface& entry,
                          const SourceText& grid_file, const SourceText& texture_map_file,
                          std::uint32_t file, TexturePictures& pictures, Diagnostics& diagnostics);

/// How far a cell's corners may lie from its plane, as a fraction of its longest diagonal.
inline constexpr double kCellFlatness = 1e-3;

}  // namespace rt
