// The texture map of a texture-mapped surface (-V, manual 2.2): one cylindrical element per cell
// of the grid, around optical centres given in grid coordinates (format in docs/formats.md,
// "Texture-mapped surfaces").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/core/rgb.h"
#include "rt/scene/read/source_text.h"

namespace rt {

/// A point of the grid in grid coordinates: u runs along a row from 0 (column 0) to the column
/// count, v from 0 (row 0) to the row count.
struct GridPoint {
    double u = 0.0;
    double v = 0.0;
};

/// One cell's element: a sphere and a cylinder centred on an optical centre, and a colour.
struct TextureElement {
    std::uint32_t centre = 0;   ///< into TextureMap::centres
    double sphere = 0.0;        ///< curvature 1/radius in the polygon file's units
    double cylinder = 0.0;      ///< the same, across the axis
    double axis_degrees = 0.0;  ///< the cylinder's axis, from the grid's u toward its v
    Rgb color{1.0, 1.0, 1.0};   ///< 0..1 each, multiplies the attribute's colour
    int line = 0;
};

/// A PNG picture the map lays on the whole grid: a colour map or a normal map.
struct MapPicture {
    std::string name;  ///< as written, relative to the texture map's folder
    int line = 0;      ///< where it is named
};

struct TextureMap {
    std::vector<GridPoint> centres;
    std::optional<MapPicture> colour_map;
    std::optional<MapPicture> normal_map;
    std::vector<TextureElement> elements;  ///< rows x columns, row by row
};

/// Reads the map, which must have `rows` x `columns` cells, as the .scn line at `named_at` says.
TextureMap read_texture_map(const SourceText& source, std::int64_t rows, std::int64_t columns,
                            const SourceLocation& named_at, Diagnostics& diagnostics);

}  // namespace rt
