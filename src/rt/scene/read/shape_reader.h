// The shape file of -M (manual 2.4): a count, then seven numbers per shape on its own $ line.
// Shapes carry no number of their own: polygons refer to them by their order, counting from 0.
#pragma once

#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/scene.h"

namespace rt {

/// The shapes in file order, with Shape::index 0, 1, 2, ... and the line each came from.
std::vector<Shape> read_shape_file(const SourceText& source, Diagnostics& diagnostics);

}  // namespace rt
