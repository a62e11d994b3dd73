// Optical surface filetype 3: a model file made by another tool (OBJ, PLY, STL, glTF, OFF and the
// other formats Assimp reads), chosen by the file name's extension. The rules, and why Assimp, are
// in docs/formats.md ("Filetype 3: model files").
#pragma once

#include <filesystem>
#include <string>

#include "rt/core/diagnostics.h"
#include "rt/core/error.h"
#include "rt/scene/read/surface_mesh.h"

namespace rt {

/// The filetype number a .scn gives a model file.
inline constexpr int kModelFiletype = 3;

/// Reads the model at `path`, which the .scn names `written` at `named_at`. Polygons keep their
/// corner count (no triangulation); vertices at the same position are joined; the file's normals
/// become corner normals; each polygon's attribute offset is its material's place among the
/// file's materials. A file that cannot be opened is an InputError at `named_at`; a broken file
/// is one InputError "file: message" (model formats give no line numbers).
SurfaceMesh read_model_file(const std::filesystem::path& path, const std::string& written,
                            const SourceLocation& named_at, Diagnostics& diagnostics);

}  // namespace rt
