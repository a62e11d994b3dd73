// The bounds, argued. Let X be where the ray's line crosses the polygon's convex hull (the
// winding test says the line passes through the polygon, up to the rounding of the corners'
// projections, which `rounding` covers), and Y = origin + t * direction the reported hit point.
//
// - Plane branch (|cos| > 1e-6): t is the plane's t, so Y is on the plane through corner 0 up to
//   rounding. Every corner is within rho of that plane, so X is too, and Y - X runs along the
//   ray: |Y - X| <= (rho + rounding) / |cos|, in any direction. Y is within `rounding` of the
//   plane.
// - Grazing branch (|cos| <= 1e-6): t lies within the corners' depths along the ray, as does X's
//   depth, so |Y - X| <= the corners' spread along the ray <= the box diagonal. Y - X runs along
//   the direction, which is within 1e-6 of the plane: its part along axis i is at most
//   diameter * sqrt(1 - n_i^2) in the plane plus 1e-6 * diameter across it, and Y is within
//   rho + 1e-6 * diameter of the plane.
// A polygon with a zero or non-finite normal always takes the grazing branch with the nearest
// corner's depth: |Y - X| <= diameter in any direction, and no slab.
#include "rt/accel/hit_regions/polygon_reach.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// Relative headroom on every bound, for the rounding of computing the bounds themselves.
constexpr double kSlack = 1.0 + 1e-9;

bool slab_meets(const Vec3& normal, const Vec3& point, double half, const Box3& box) {
    if (!std::isfinite(half)) {
        return true;
    }
    // The box's extent along the normal, from its centre.
    const Vec3 centre = (box.lo + box.hi) * 0.5;
    const Vec3 extent = (box.hi - box.lo) * 0.5;
    const double radius = std::fabs(normal.x) * extent.x + std::fabs(normal.y) * extent.y +
                          std::fabs(normal.z) * extent.z;
    const double offset = std::fabs(dot(normal, centre - point));
    return offset <= (half + radius) * kSlack + 1e-15 * box.magnitude();
}

}  // namespace

PolygonPlane polygon_plane(const Scene& scene, std::uint32_t id, double rounding) {
    const Polygon& polygon = scene.polygons[id];
    PolygonPlane plane;
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
        plane.corners.add(scene.corner_position(polygon, k));
    }
    plane.diameter = length(plane.corners.extent()) * kSlack;
    plane.rounding = rounding * kSlack + 4e-16 * plane.corners.magnitude();
    // The test compares |dot(normal, d)| with 1e-6 |d|: for a normal of length L that is
    // |cos| against 1e-6 / L. A zero or non-finite normal makes every ray grazing.
    const double normal_length = length(polygon.normal);
    if (!std::isfinite(normal_length) || normal_length == 0.0) {
        return plane;
    }
    plane.usable = true;
    plane.normal = polygon.normal / normal_length;
    plane.grazing_cosine = std::min(kGrazingCosine / normal_length, 1.0);
    plane.point = scene.corner_position(polygon, 0);
    double rho = 0.0;  // the corners' largest distance from the plane through corner 0
    for (std::uint32_t k = 1; k < polygon.corner_count; ++k) {
        rho = std::max(
            rho, std::fabs(dot(plane.normal, scene.corner_position(polygon, k) - plane.point)));
    }
    plane.rho = rho * kSlack + plane.rounding;
    return plane;
}

PolygonReach polygon_reach(const Scene& scene, std::uint32_t id, double min_cos, double rounding) {
    const PolygonPlane plane = polygon_plane(scene, id, rounding);
    const Box3& corners = plane.corners;
    const double diameter = plane.diameter;
    rounding = plane.rounding;
    PolygonReach reach;
    if (!plane.usable) {
        reach.box = corners.grown(rounding);
        reach.grazing_box = corners.grown(diameter + rounding);
        reach.grazing_cosine = 1.0;
        return reach;
    }
    const Vec3& n = plane.normal;
    const double grazing = plane.grazing_cosine;
    const double rho = plane.rho;
    reach.plane_point = plane.point;
    reach.normal = n;
    reach.grazing_cosine = grazing;

    reach.box = corners.grown((rho + rounding) / std::max(min_cos, grazing / kSlack) * kSlack);
    reach.slab_half = 2.0 * rounding * kSlack;
    if (min_cos <= grazing) {
        const double across = 2.0 * grazing * diameter;
        Vec3 growth;
        for (int axis = 0; axis < 3; ++axis) {
            const double in_plane = diameter * std::sqrt(std::max(0.0, 1.0 - n[axis] * n[axis]));
            growth[axis] = (in_plane + across) * kSlack + rounding;
        }
        reach.grazing_box = corners.grown(growth);
        reach.grazing_slab_half = (rho + across + 2.0 * rounding) * kSlack;
    }
    return reach;
}

// A line through X (in the hull) and E' (within `slack` of `point`) has
// |cos| = |dot(n, X - E')| / |X - E'| >= (h - rho - slack) / (L + slack), where h is the
// point's distance from the plane through corner 0 and L the farthest corner from it.
double min_cosine_through(const Scene& scene, std::uint32_t id, const Vec3& point, double slack) {
    const Polygon& polygon = scene.polygons[id];
    const double normal_length = length(polygon.normal);
    if (!std::isfinite(normal_length) || normal_length == 0.0) {
        return 0.0;
    }
    const Vec3 n = polygon.normal / normal_length;
    const Vec3 c0 = scene.corner_position(polygon, 0);
    double rho = 0.0;
    double farthest = 0.0;
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
        const Vec3 c = scene.corner_position(polygon, k);
        rho = std::max(rho, std::fabs(dot(n, c - c0)));
        farthest = std::max(farthest, length(c - point));
    }
    const double height = std::fabs(dot(n, c0 - point));
    const double bound = (height - rho * kSlack - slack) / ((farthest + slack) * kSlack);
    return std::isfinite(bound) ? std::max(bound * (1.0 - 1e-9), 0.0) : 0.0;
}

bool slab_meets_box(const PolygonReach& reach, const Box3& box) {
    return slab_meets(reach.normal, reach.plane_point, reach.slab_half, box);
}

bool grazing_slab_meets_box(const PolygonReach& reach, const Box3& box) {
    return slab_meets(reach.normal, reach.plane_point, reach.grazing_slab_half, box);
}

}  // namespace rt
