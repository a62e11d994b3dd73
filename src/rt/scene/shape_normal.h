// Normals inferred from the sphere, cylinder and cone shapes of -M (manual 2.4).
#pragma once

#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

/// The outward normal of the shape at `point` for a polygon of mark Sphere (point - centre),
/// Cylinder (the part of point - axis point perpendicular to the axis) or Cone (the normal of the
/// infinite cone, half-angle in degrees, along the line from the apex through the point), turned
/// to agree with the polygon's outward normal. The polygon's normal for the other marks and
/// wherever the shape gives none (the point on the axis, a zero axis, ...).
Vec3 shape_normal(const Shape& shape, PolygonMark mark, const Vec3& point,
                  const Vec3& polygon_normal);

}  // namespace rt
