// Shading normals: interpolated over polygons of any number of corners (the manual's "fast
// normal interpolation scheme for polygons of any number of edges"), and inferred from the
// sphere, cylinder and cone shapes of -M (manual 2.4).
#pragma once

#include <cstdint>
#include <span>

#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

/// Mean value coordinates (Floater 2003) of `point` in the planar polygon `corners` with unit
/// normal `normal`: weights summing to 1, exact at the corners and along the edges, smooth inside,
/// and valid for concave polygons. weights.size() must equal corners.size().
void mean_value_weights(std::span<const Vec3> corners, const Vec3& normal, const Vec3& point,
                        std::span<double> weights);

/// The vertex normals of the polygon's corners blended by mean value coordinates; the polygon's
/// own normal where they cancel out.
Vec3 interpolated_normal(const Scene& scene, std::uint32_t polygon, const Vec3& point);

/// The outward normal of the shape at `point` for a polygon of mark Sphere, Cylinder or Cone,
/// turned to agree with the polygon's outward normal; that normal where the shape gives none.
Vec3 shape_normal(const Shape& shape, PolygonMark mark, const Vec3& point,
                  const Vec3& polygon_normal);

}  // namespace rt
