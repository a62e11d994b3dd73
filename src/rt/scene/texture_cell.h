// One cell of a texture-mapped optical surface (-V, manual 2.2) in world space: the cell's tangent
// frame and its cylindrical element, which bends the cell's normal as a sphere and a cylinder
// would and tints its colour (docs/formats.md, "Texture-mapped surfaces"; docs/rendering.md).
#pragma once

#include <cstdint>

#include "rt/core/rgb.h"
#include "rt/core/vec3.h"

namespace rt {

/// The largest sine of the angle by which an element tilts the normal: beyond the edge of its
/// sphere or cylinder (distance >= radius) the surface keeps the slope it has at 0.99 of the
/// radius, a tilt of about 81.9 degrees.
inline constexpr double kMaxElementTiltSine = 0.99;

struct TextureCell {
    Vec3 tangent_u;       ///< unit, in the cell's plane, along the grid's rows (increasing u)
    Vec3 tangent_v;       ///< unit, in the cell's plane, perpendicular to tangent_u (increasing v)
    Vec3 optical_centre;  ///< world point the element's sphere and cylinder are centred on
    Vec3 across_axis;     ///< unit, in the cell's plane, perpendicular to the cylinder's axis
    double sphere = 0.0;  ///< curvature 1/radius in world units; > 0 bulges to the outside
    double cylinder = 0.0;     ///< the same, across the cylinder's axis only
    Rgb color{1.0, 1.0, 1.0};  ///< multiplies the attribute's colour
    std::uint32_t grid = 0;    ///< into Scene::texture_grids
    std::uint32_t row = 0;     ///< where the cell is in its grid
    std::uint32_t column = 0;

    bool flat() const { return sphere == 0.0 && cylinder == 0.0; }
};

/// A texture-mapped surface's grid as a whole: its size, and the pictures its texture map lays on
/// it (docs/formats.md, "Pictures on the grid").
struct TextureGrid {
    /// Not an index into Scene::texture_images: the grid has no such picture.
    static constexpr std::int32_t kNoImage = -1;
    std::uint32_t rows = 0;
    std::uint32_t columns = 0;
    std::int32_t colour_map = kNoImage;  ///< into Scene::texture_images
    std::int32_t normal_map = kNoImage;  ///< into Scene::texture_images

    bool has_images() const { return colour_map != kNoImage || normal_map != kNoImage; }
};

/// The tangent of the tilt of the normal of a sphere or cylinder of curvature k at distance rho
/// from its centre or axis, divided by rho: k / sqrt(1 - (k rho)^2), held at the slope of
/// kMaxElementTiltSine beyond it. Times the offset from the centre, it is the in-plane part of
/// the normal over its out-of-plane part (exact, not paraxial).
double element_slope(double k, double rho);

/// The outward normal of the cell's element at `point` (on the cell): the geometric `normal`
/// turned as the gradient of the summed heights of the sphere and the cylinder turns it. A flat
/// element returns `normal` itself, bit for bit.
Vec3 element_normal(const TextureCell& cell, const Vec3& normal, const Vec3& point);

}  // namespace rt
