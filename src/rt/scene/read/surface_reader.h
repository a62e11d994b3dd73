// Reads an optical surface file of any filetype (manual 2.5, and model files) into a SurfaceMesh.
#pragma once

#include <filesystem>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/read/surface_mesh.h"
#include "rt/scene/scene.h"

namespace rt {

/// Reads the file at `path` that `surface` names: filetype 0 (polygon file), 1 (Phigs+ subset),
/// 2 (Prinz polygonizer) or 3 (a model file, rt/scene/read/model_reader.h). With -M only
/// filetype 0 carries marks, the others are read with every polygon Ordinary.
SurfaceMesh read_optical_surface(const std::filesystem::path& path, const OpticalSurface& surface,
                                 const ReaderDialect& dialect, Diagnostics& diagnostics);

}  // namespace rt
