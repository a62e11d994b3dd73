// Axis-aligned boxes for the voxel methods (SEADS and the octree): the world box, voxel bounds,
// and where a ray enters and leaves one.
#pragma once

#include <algorithm>
#include <utility>

#include "rt/core/bounds.h"
#include "rt/core/ray.h"
#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

/// The box the voxel methods subdivide: the scene's bounds grown by a small margin (so that no
/// polygon lies on the world's own faces) and never flat (a planar scene still gets some depth).
/// With `cube`, every side is the largest (the octree halves one cube).
Box3 world_box(const Scene& scene, bool cube);

/// "The fudge" (-of turns it off): how far every voxel is grown when deciding which polygons go
/// into it, 2^-24 of the world's largest side. The walk's voxel boundaries and entry point are
/// computed in floating point and may cut a voxel's corner by rounding; with every polygon also
/// filed in the voxels within the fudge of it, a polygon the ray touches is still met. (The
/// rounding of the hit's own t is the per-ray slack's job: near_hit_rule.h.) Zero with -of.
double voxel_fudge(const Box3& world, bool no_fudge);

/// The smallest box around the polygon's corners.
Box3 polygon_bounds(const Scene& scene, std::uint32_t polygon);

/// The part of the ray's t range inside the closed box, intersected with `within`; none if empty.
/// A direction component of zero is handled exactly (no 0 * infinity).
bool clip_to_box(const Ray& ray, const Box3& box, Interval within, Interval& inside);
/// The same with the reciprocals already at hand: inverse[a] is 1 / ray.direction[a] wherever
/// that is not zero (the walks and the line probe share them; the same values, the same answer).
/// Inline: called out of line, GCC passed the interval through the stack in a way that stalled
/// on its own store (half of the call's samples).
inline bool clip_to_box(const Ray& ray, const Vec3& inverse, const Box3& box, Interval within,
                        Interval& inside) {
    double near = within.min;
    double far = within.max;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis];
        const double d = ray.direction[axis];
        if (d == 0.0) {
            if (o < box.lo[axis] || o > box.hi[axis]) {
                return false;
            }
            continue;
        }
        double t0 = (box.lo[axis] - o) * inverse[axis];
        double t1 = (box.hi[axis] - o) * inverse[axis];
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        near = std::max(near, t0);
        far = std::min(far, t1);
    }
    if (!(near <= far)) {
        return false;
    }
    inside = {near, far};
    return true;
}

}  // namespace rt
