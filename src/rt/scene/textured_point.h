// What a texture-mapped polygon (-V) shows at a point of it: the normal its cell's element and the
// grid's normal map give, and the colour its element and colour map give (docs/formats.md,
// "Texture-mapped surfaces"; docs/rendering.md).
#pragma once

#include <cstdint>

#include "rt/core/rgb.h"
#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

/// A point in grid coordinates: u along the rows (0 at column 0), v across them (0 at row 0).
struct GridCoordinates {
    double u = 0.0;
    double v = 0.0;
};

struct TexturedPoint {
    Vec3 normal;  ///< outward, unit
    Rgb color;    ///< multiplies the attribute's colour
};

/// The normal and colour factor at `point` on texture-mapped polygon `polygon`.
TexturedPoint textured_point(const Scene& scene, std::uint32_t polygon, const Vec3& point);

/// The colour of polygon `polygon` at `point`: its attribute's, times its texture's there.
Rgb surface_color(const Scene& scene, std::uint32_t polygon, const Vec3& point);

/// Where `point` (on the cell's polygon) is in grid coordinates: the inverse of the bilinear map
/// of the cell's corners, measured in the cell's plane, clamped to the cell.
GridCoordinates grid_coordinates(const Scene& scene, std::uint32_t polygon, const Vec3& point);

/// The outward normal a normal-map pixel `texel` (channels 0 to 1) gives a surface of outward
/// normal `normal` whose grid runs along `tangent_u` and `tangent_v`: red along u, green toward
/// decreasing v (up the picture), blue along the normal, each channel mapped from 0..1 to -1..1.
Vec3 normal_map_normal(const Rgb& texel, const Vec3& normal, const Vec3& tangent_u,
                       const Vec3& tangent_v);

}  // namespace rt
