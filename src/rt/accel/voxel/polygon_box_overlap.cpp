#include "rt/accel/voxel/polygon_box_overlap.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rt {

namespace {

// Gives every comparison a relative margin in the polygon's favour, far above the rounding of a
// few products and sums, so that a polygon lying exactly in a voxel face goes into both voxels.
constexpr double kSlack = 0x1p-40;

// Whether the corners (relative to the box centre) and the box of half-size `half` are apart
// along `axis`.
bool separated_along(const Vec3& axis, const Vec3* corners, std::uint32_t count, const Vec3& half) {
    const double reach =
        half.x * std::fabs(axis.x) + half.y * std::fabs(axis.y) + half.z * std::fabs(axis.z);
    double lo = dot(axis, corners[0]);
    double hi = lo;
    for (std::uint32_t k = 1; k < count; ++k) {
        const double p = dot(axis, corners[k]);
        lo = std::min(lo, p);
        hi = std::max(hi, p);
    }
    const double slack = kSlack * (reach + std::max(std::fabs(lo), std::fabs(hi)));
    return lo > reach + slack || hi < -reach - slack;
}

Vec3 unit_axis(int i) {
    return i == 0 ? Vec3{1, 0, 0} : (i == 1 ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
}

bool overlaps(const Vec3* corners, std::uint32_t count, const Vec3& normal, const Vec3& half) {
    for (int i = 0; i < 3; ++i) {
        if (separated_along(unit_axis(i), corners, count, half)) {
            return false;
        }
    }
    if (separated_along(normal, corners, count, half)) {
        return false;
    }
    for (std::uint32_t k = 0; k < count; ++k) {
        const Vec3 edge = corners[(k + 1) % count] - corners[k];
        for (int i = 0; i < 3; ++i) {
            const Vec3 axis = cross(edge, unit_axis(i));
            if ((axis.x != 0.0 || axis.y != 0.0 || axis.z != 0.0) &&
                separated_along(axis, corners, count, half)) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace

bool polygon_overlaps_box(const Scene& scene, std::uint32_t polygon, const Box3& box) {
    const Polygon& p = scene.polygons[polygon];
    const Vec3 centre = (box.lo + box.hi) * 0.5;
    const Vec3 half = (box.hi - box.lo) * 0.5;
    // Corners relative to the box centre keep the products small; most polygons are triangles or
    // quads, so a stack buffer serves nearly all.
    constexpr std::uint32_t kOnStack = 16;
    Vec3 local[kOnStack];
    std::vector<Vec3> many;
    Vec3* corners = local;
    if (p.corner_count > kOnStack) {
        many.resize(p.corner_count);
        corners = many.data();
    }
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        corners[k] = scene.corner_position(p, k) - centre;
    }
    return overlaps(corners, p.corner_count, p.normal, half);
}

}  // namespace rt
