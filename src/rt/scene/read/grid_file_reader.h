// The polygon file of a texture-mapped surface (-V, manual 2.2): a grid of near-rectangles given
// by its points (format in docs/formats.md, "Texture-mapped surfaces").
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/core/vec3.h"
#include "rt/scene/read/dollar_lines.h"
#include "rt/scene/read/source_text.h"

namespace rt {

struct PolygonGrid {
    std::int64_t rows = 0;  ///< of cells; the points are one more each way
    std::int64_t columns = 0;
    std::vector<Vec3> points;  ///< (rows + 1) x (columns + 1), row by row
    std::vector<int> lines;    ///< where each point is written

    std::size_t point_index(std::int64_t row, std::int64_t column) const {
        return static_cast<std::size_t>(row * (columns + 1) + column);
    }
    const Vec3& point(std::int64_t row, std::int64_t column) const {
        return points[point_index(row, column)];
    }
};

/// Reads the grid, which must have `rows` x `columns` cells, as the .scn line at `named_at`
/// says.
PolygonGrid read_grid_file(const SourceText& source, std::int64_t rows, std::int64_t columns,
                           const SourceLocation& named_at, Diagnostics& diagnostics);

/// Reads the record "ROWS COLUMNS" that starts both -V files, and checks it against the .scn.
void expect_grid_size(const SourceText& source, const DollarLine& record, std::int64_t rows,
                      std::int64_t columns, const SourceLocation& named_at);

}  // namespace rt
