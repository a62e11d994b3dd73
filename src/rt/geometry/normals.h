// Shading normals interpolated over polygons of any number of corners (the manual's "fast normal
// interpolation scheme for polygons of any number of edges"). The normals inferred from the -M
// shapes are the scene's (rt/scene/shape_normal.h).
#pragma once

#include <cstdint>
#include <span>

#include "rt/core/vec3.h"
#include "rt/geometry/polygon_view.h"

namespace rt {

/// Mean value coordinates (Floater 2003; Hormann and Floater 2006) of `point` in the planar
/// polygon `corners` with unit normal `normal`, measured in the polygon's plane: weights summing
/// to 1, exactly 1 at a corner the point equals, linear along the edges, smooth inside, valid for
/// convex and concave polygons, reproducing linear functions. Only the first corners.size()
/// weights are written; weights.size() must be at least corners.size(). Equal weights where the
/// coordinates are undefined (a degenerate polygon).
void mean_value_weights(std::span<const Vec3> corners, const Vec3& normal, const Vec3& point,
                        std::span<double> weights);

/// The mean value coordinates of `point` in the polygon, one per corner in loop order;
/// weights.size() must be at least the polygon's corner count.
void polygon_weights(const PolygonView& polygon, const Vec3& point, std::span<double> weights);

/// The unit normals at the polygon's corners blended by its mean value coordinates at `point`;
/// the polygon's own normal where they cancel out or there are none.
Vec3 interpolated_normal(const PolygonView& polygon, const CornerNormals& normals,
                         const Vec3& point);

}  // namespace rt
