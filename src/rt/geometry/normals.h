// Shading normals: interpolated over polygons of any number of corners (the manual's "fast
// normal interpolation scheme for polygons of any number of edges"), and inferred from the
// sphere, cylinder and cone shapes of -M (manual 2.4).
#pragma once

#include <cstdint>
#include <span>

#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

/// Mean value coordinates (Floater 2003; Hormann and Floater 2006) of `point` in the planar
/// polygon `corners` with unit normal `normal`, measured in the polygon's plane: weights summing
/// to 1, exactly 1 at a corner the point equals, linear along the edges, smooth inside, valid for
/// convex and concave polygons, reproducing linear functions. Only the first corners.size()
/// weights are written; weights.size() must be at least corners.size(). Equal weights where the
/// coordinates are undefined (a degenerate polygon).
void mean_value_weights(std::span<const Vec3> corners, const Vec3& normal, const Vec3& point,
                        std::span<double> weights);

/// The mean value coordinates of `point` in scene polygon `polygon`, one per corner in loop
/// order; weights.size() must be at least the polygon's corner count.
void polygon_weights(const Scene& scene, std::uint32_t polygon, const Vec3& point,
                     std::span<double> weights);

/// The unit vertex normals of the polygon's corners blended by its mean value coordinates at
/// `point`; the polygon's own normal where they cancel out or the scene has no vertex normals.
Vec3 interpolated_normal(const Scene& scene, std::uint32_t polygon, const Vec3& point);

/// The outward normal of the shape at `point` for a polygon of mark Sphere (point - centre),
/// Cylinder (the part of point - axis point perpendicular to the axis) or Cone (the normal of the
/// infinite cone, half-angle in degrees, along the line from the apex through the point), turned
/// to agree with the polygon's outward normal. The polygon's normal for the other marks and
/// wherever the shape gives none (the point on the axis, a zero axis, ...).
Vec3 shape_normal(const Shape& shape, PolygonMark mark, const Vec3& point,
                  const Vec3& polygon_normal);

}  // namespace rt
