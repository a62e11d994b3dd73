// The .scn file (manual 2.2) as written: header, view, where the attributes are, the optional
// shape file, and each entity's optical surfaces with their placement. Files are not opened here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/scene.h"

namespace rt {

/// A file name as the .scn writes it, and where.
struct NamedFile {
    std::string name;
    SourceLocation where;
};

/// Scale, then rotation about x, y and z (degrees), then translation (manual 2.2).
struct SurfacePlacement {
    double scale = 1.0;
    Vec3 translation;
    Vec3 rotation_degrees;
};

struct ScnSurface {
    OpticalSurface surface;
    SurfacePlacement placement;
};

/// A texture-mapped optical surface of -V (manual 2.2): a grid of near-rectangles and the
/// texture map of its cells.
struct ScnTexturedSurface {
    long attribute_number = 0;
    NamedFile polygon_file;
    NamedFile texture_map;
    SurfacePlacement placement;
    std::int64_t rows = 0;  ///< of cells
    std::int64_t columns = 0;
    SourceLocation where;
};

struct ScnFile {
    SceneHeader header;
    SceneView view;
    SourceLocation eye_at;                     ///< for a look point that auto-centering moves
    std::optional<NamedFile> attributes_file;  ///< absent with -Df
    std::vector<Attribute> inline_attributes;  ///< the -Df block
    std::optional<NamedFile> shape_file;       ///< the $@name line (-M)
    std::vector<ScnSurface> surfaces;
    std::vector<ScnTexturedSurface> textured_surfaces;  ///< -V
};

/// Reads and checks the .scn under the dialect (rules in docs/formats.md).
ScnFile read_scn(const SourceText& source, const ReaderDialect& dialect, Diagnostics& diagnostics);

}  // namespace rt
