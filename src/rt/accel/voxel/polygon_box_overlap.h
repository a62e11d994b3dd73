// Which voxels a polygon goes into: the separating-axis test of a polygon against a box.
#pragma once

#include <cstdint>

#include "rt/accel/voxel/box.h"
#include "rt/scene/scene.h"

namespace rt {

/// Whether the polygon may touch the closed box. Exact for a planar convex polygon (up to a
/// relative 2^-40 in its favour); for a concave or warped one it answers for the convex hull of
/// its corners, so it never leaves out a voxel the polygon touches. The axes tried are the box's
/// three, the polygon's normal, and each edge crossed with each box axis (Gottschalk's set for
/// a flat convex polygon); projecting every corner on each keeps any of them a valid separator
/// whatever the polygon's shape.
bool polygon_overlaps_box(const Scene& scene, std::uint32_t polygon, const Box3& box);

}  // namespace rt
