#include "rt/accel/voxel/box.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// The world's margin, relative to its largest side: far larger than any rounding, far smaller
// than any voxel of interest (2^-20 of the world is the finest octree level).
constexpr double kWorldMargin = 0x1p-12;

}  // namespace

double voxel_fudge(const Box3& world, bool no_fudge) {
    return no_fudge ? 0.0 : world.largest_extent() * 0x1p-24;
}

Box3 world_box(const Scene& scene, bool cube) {
    Box3 box = scene.bounds();
    double side = box.largest_extent();
    if (!(side > 0.0)) {
        // One point (or no polygon at all): any size will do, relative to where it is.
        side = std::max({1.0, std::fabs(box.lo.x), std::fabs(box.lo.y), std::fabs(box.lo.z)});
    }
    const double margin = side * kWorldMargin;
    for (int axis = 0; axis < 3; ++axis) {
        // A flat axis gets a thickness, and with `cube` every axis the full side.
        const double want = cube ? side : std::max(box.hi[axis] - box.lo[axis], side * 0x1p-8);
        const double middle = 0.5 * (box.lo[axis] + box.hi[axis]);
        box.lo[axis] = std::min(box.lo[axis], middle - 0.5 * want) - margin;
        box.hi[axis] = std::max(box.hi[axis], middle + 0.5 * want) + margin;
    }
    return box;
}

Box3 polygon_bounds(const Scene& scene, std::uint32_t polygon) {
    const Polygon& p = scene.polygons[polygon];
    Box3 box = Box3::around(scene.corner_position(p, 0));
    for (std::uint32_t k = 1; k < p.corner_count; ++k) {
        box.add(scene.corner_position(p, k));
    }
    return box;
}

bool clip_to_box(const Ray& ray, const Box3& box, Interval within, Interval& inside) {
    // A product with the reciprocal rather than two divisions: an ulp or so apart, far below
    // the world's margin. (A NaN from 0 * inf, for a denormal d, leaves the axis unclipped.)
    Vec3 inverse;
    for (int axis = 0; axis < 3; ++axis) {
        inverse[axis] = ray.direction[axis] == 0.0 ? 0.0 : 1.0 / ray.direction[axis];
    }
    return clip_to_box(ray, inverse, box, within, inside);
}

}  // namespace rt
