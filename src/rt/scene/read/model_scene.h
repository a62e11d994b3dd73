// `rt --model FILE`: a scene made around one model file, without a .scn (docs/formats.md, "A model
// without a scene"): the model scaled to a standard size and set on a checkerboard floor, a square
// light above it, and a camera framing it from in front, to the right and above.
#pragma once

#include <filesystem>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/scene.h"

namespace rt {

/// The largest side of the model's bounding box once placed, in scene units.
inline constexpr double kModelSize = 10.0;

/// Reads the model (any format read_model_file() takes) and builds the scene around it with the
/// scene builder, as load_scene() does for a .scn. With -Po/-Pt (dialect.smooth_shade_field) the
/// model is smooth-shaded; the dialect's other fields describe .scn and Attributes files and
/// change nothing here. Errors are InputErrors naming the model file.
Scene model_scene(const std::filesystem::path& model, const ReaderDialect& dialect,
                  Diagnostics& diagnostics);

}  // namespace rt
