// Reads a .scn file and everything it names into the flat Scene (manual 2.2-2.5; the formats and
// every decision about them are in docs/formats.md).
#pragma once

#include <filesystem>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/read/textured_surface.h"
#include "rt/scene/scene.h"

namespace rt {

/// Reads the scene. File names in it are relative to the .scn file's folder. Malformed input
/// throws InputError ("file:line: message"); warnings, notes (auto-centering) and -df traces go
/// to `diagnostics`. `check_pictures` sees each texture picture's size before it is decoded (a
/// file named by several maps is decoded once).
Scene load_scene(const std::filesystem::path& scn_file, const ReaderDialect& dialect,
                 Diagnostics& diagnostics, const PictureCheck& check_pictures = {});

}  // namespace rt
