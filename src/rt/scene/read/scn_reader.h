// The .scn file (manual 2.2) as written: header, view, where the attributes are, the optional
// shape file, and each entity's optical surfaces with their placement. Files are not opened here.
#pragma once

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

struct ScnFile {
    SceneHeader header;
    SceneView view;
    SourceLocation eye_at;                     ///< for a look point that auto-centering moves
    std::optional<NamedFile> attributes_file;  ///< absent with -Df
    std::vector<Attribute> inline_attributes;  ///< the -Df block
    std::optional<NamedFile> shape_file;       ///< the $@name line (-M)
    std::vector<ScnSurface> surfaces;
};

/// Reads and checks the .scn under the dialect (rules in docs/formats.md).
ScnFile read_scn(const SourceText& source, const ReaderDialect& dialect, Diagnostics& diagnostics);

}  // namespace rt
