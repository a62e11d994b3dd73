// Why this test is watertight, and why it never hits twice.
//
// 1. Every corner is carried into the ray's 2D space by RaySpace::project: the same operations
//    on the same inputs, so a corner shared by neighbouring polygons has the same (x, y) bits in
//    each. The ray is the point (0, 0) there.
//
// 2. Inside or outside is Sunday's winding number of (0, 0). An edge a->b crosses upward when
//    y_a <= 0 < y_b and downward when y_b <= 0 < y_a; an upward crossing counts +1 if the edge
//    function E = x_a*y_b - y_a*x_b is > 0 (the edge passes to the right of the ray), a downward
//    one -1 if E < 0. The sign of E is EXACT (edge_sign: a filtered float evaluation, exact
//    expansion arithmetic when it is too close to call), so every decision is the exact one for
//    the projected corners.
//
// 3. Those rules are exactly the exact winding number of the displaced point P = (e, e^2) for an
//    infinitesimal e > 0. Half-open in y: a corner with y == 0 is below P. On an edge crossing
//    y = 0, E(P) = E(0) - e (y_b - y_a) + e^2 (x_b - x_a); with E(0) == 0 the e term decides, and
//    it is negative for an upward edge and positive for a downward one, i.e. "not counted", which
//    is what the strict signs give. P lies on no projected edge and on no corner (E(P) vanishes
//    for every small e only when the edge has zero length), so the displaced ray meets no edge or
//    corner of any polygon.
//
// 4. The degenerate zero-E cases on the ray's own line need nothing more:
//    - the ray through a corner or along an edge's projection (E == 0, or a corner at (0, 0)):
//      decided by P as in 3, the same way for every polygon sharing that corner or edge;
//    - an edge lying on y == 0 (horizontal through the ray): both ends are "below" P, so it never
//      crosses, in either direction, for either neighbour;
//    - a polygon seen edge-on (the ray in its plane): exactly, its projection has no area and P is
//      outside it. But its corners' rounded projections may enclose a sliver of area around P;
//      then the displaced ray really does pass through it (and not through the neighbours on that
//      side), so it must count as a hit or there would be a crack. The plane gives no usable depth
//      for such a grazing hit, so it is taken from the corners: the plane's t (the nearest
//      corner's depth for a ray exactly parallel to the plane) clamped first to the span of t
//      where the line is inside the corners' box (grown by 2^-40 of the coordinates' size), then
//      to the range of the corners' depths along the ray. Where the line really meets the
//      polygon, at X, X's t is in both ranges; the winding test may accept a line that passes
//      within the projection's rounding (about 2^-49 of the size) of the polygon instead, and
//      then both ranges still hold a t of the line within that distance of the polygon. So the
//      two overlap, up to that distance, and the hit lies where the line is in the corner box
//      (an accelerator can cull a box by where the line enters and leaves it) and within the
//      corners' depths (the hit-region bounds in accel/hit_regions rely on that).
//
// 5. So every polygon is asked the same question, exactly: does it contain the one displaced point
//    P? P lies on no edge and no corner, so of the polygons whose projections meet around a shared
//    edge or corner the ray crosses, exactly one contains it: never none (no crack), never two (no
//    double hit). This holds whichever way the neighbours' loops run. With consistently oriented
//    loops the neighbour walks the shared edge as b->a: the crossing classes swap (upward for one
//    is downward for the other, by the same comparisons) and edge_sign(b, a) == -edge_sign(a, b),
//    so the edge adds +1 to one polygon exactly when it adds -1 to the other.
//
// The depth t comes from each polygon's own plane; it does not take part in the decision above.
// The argument assumes IEEE double without fused multiply-adds in project() (the project builds
// in ISO mode, where GCC and Clang do not contract across statements); edge_sign is exact either
// way.
#include "rt/geometry/ray_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rt/geometry/exact_edge_sign.h"

namespace rt {

namespace {

constexpr double kEpsilon = 0x1p-53;
// Shewchuk's bound on the rounding error of a*b - c*d: (3 eps + 16 eps^2) (|a*b| + |c*d|).
constexpr double kEdgeErrorBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
// Below this the products may have lost bits to underflow and the bound no longer holds.
constexpr double kSmallestTrusted = 0x1p-900;

// Sunday's winding number over any source of corners, so the span and the PolygonView forms share
// one loop (and therefore one decision). Compiled once for each axis the ray may be largest along:
// with the axes known, a corner's projection reads its coordinates directly instead of choosing
// each among three at run time (3 % of the instructions of a packet walk on a small mesh).
template <int Kz, class CornerAt>
int winding_dropping(const RaySpace& space, std::uint32_t count, CornerAt corner_at) {
    int winding = 0;
    double xa = 0.0;
    double ya = 0.0;
    space.project_dropping<Kz>(corner_at(count - 1), xa, ya);
    for (std::uint32_t k = 0; k < count; ++k) {
        double xb = 0.0;
        double yb = 0.0;
        space.project_dropping<Kz>(corner_at(k), xb, yb);
        if (ya <= 0.0) {
            if (yb > 0.0 && edge_sign(xa, ya, xb, yb) > 0) {
                ++winding;
            }
        } else if (yb <= 0.0 && edge_sign(xa, ya, xb, yb) < 0) {
            --winding;
        }
        xa = xb;
        ya = yb;
    }
    return winding;
}

template <class CornerAt>
int winding_of(const RaySpace& space, std::uint32_t count, CornerAt corner_at) {
    if (!space.valid() || count < 3) {
        return 0;
    }
    switch (space.dropped_axis()) {
        case 0:
            return winding_dropping<0>(space, count, corner_at);
        case 1:
            return winding_dropping<1>(space, count, corner_at);
        default:
            return winding_dropping<2>(space, count, corner_at);
    }
}

bool inside(double t, Interval interval) {
    return t > interval.min && t < interval.max;
}

constexpr double kMiss = std::numeric_limits<double>::quiet_NaN();
// A grazing hit's corner box is grown by this times the largest |coordinate| of corners and
// origin: far above the 2^-49 of the projection's rounding, far below the BVH's 2^-20 margins.
constexpr double kGrazingBoxMargin = 0x1p-40;

// The range of the corners' depths (t of their projections onto the ray). Through the unit
// direction, not dot(d, d), which overflows or underflows for directions far from unit length.
template <class CornerAt>
void corner_depths(const RaySpace& space, std::uint32_t count, CornerAt corner_at, double& nearest,
                   double& farthest) {
    const Vec3& origin = space.ray().origin;
    const Vec3 unit = space.unit_direction();
    const double length = space.direction_length();
    nearest = farthest = dot(corner_at(0) - origin, unit) / length;
    for (std::uint32_t k = 1; k < count; ++k) {
        const double depth = dot(corner_at(k) - origin, unit) / length;
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
}

// Where the ray's line is inside the polygon's corner box grown by a rounding margin: [lo, hi] in
// t. Axes the direction does not move along do not constrain it. Returns false when no t is
// (possible only with non-finite input: the winding test accepted a line that passes within the
// projection's rounding, far below the margin, of the polygon).
template <class CornerAt>
bool span_in_corner_box(const Ray& ray, std::uint32_t count, CornerAt corner_at, double& lo,
                        double& hi) {
    Vec3 box_lo = corner_at(0);
    Vec3 box_hi = box_lo;
    double size = 0.0;
    for (std::uint32_t k = 0; k < count; ++k) {
        const Vec3 c = corner_at(k);
        for (int axis = 0; axis < 3; ++axis) {
            box_lo[axis] = std::min(box_lo[axis], c[axis]);
            box_hi[axis] = std::max(box_hi[axis], c[axis]);
            size = std::max(size, std::fabs(c[axis]));
        }
    }
    const Vec3& o = ray.origin;
    const double margin =
        kGrazingBoxMargin * (size + std::max({std::fabs(o.x), std::fabs(o.y), std::fabs(o.z)}));
    lo = -HUGE_VAL;
    hi = HUGE_VAL;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = ray.direction[axis];
        if (d == 0.0) {
            continue;
        }
        const double a = (box_lo[axis] - margin - o[axis]) / d;
        const double b = (box_hi[axis] + margin - o[axis]) / d;
        lo = std::max(lo, std::min(a, b));
        hi = std::min(hi, std::max(a, b));
    }
    return lo <= hi;  // false for a NaN too
}

// The one hit test behind every public form (NaN for a miss): the decision is the winding number
// alone; the depth is the plane's, or for a polygon seen (nearly) edge-on the clamped depth argued
// above.
template <class CornerAt>
double hit_of(const RaySpace& space, const Vec3& normal, std::uint32_t count, CornerAt corner_at,
              Interval t) {
    if (!space.valid() || count < 3) {
        return kMiss;
    }
    const Ray& ray = space.ray();
    const double denominator = dot(normal, ray.direction);
    const double along = plane_depth(ray, normal, corner_at(0), denominator);
    // (plane_certainly_missed, ray_polygon.h, asks the same first, without the RaySpace.)
    if (std::fabs(denominator) > space.grazing_limit() && std::isfinite(along)) {
        // The plane first: one dot product rejects most polygons before any corner is projected.
        if (!inside(along, t) || winding_of(space, count, corner_at) == 0) {
            return kMiss;
        }
        return along;
    }
    if (winding_of(space, count, corner_at) == 0) {
        return kMiss;
    }
    double nearest = 0.0;
    double farthest = 0.0;
    corner_depths(space, count, corner_at, nearest, farthest);
    // Into the span where the line is inside the corner box, then into the corners' depths: the
    // span keeps the hit where a box-culling accelerator looks for it, the depths keep it where
    // the hit-region bounds (accel/hit_regions) expect it. The two overlap up to the margin (see
    // 4 above).
    double depth = std::isfinite(along) ? along : nearest;
    double span_lo = 0.0;
    double span_hi = 0.0;
    if (span_in_corner_box(ray, count, corner_at, span_lo, span_hi)) {
        depth = std::clamp(depth, span_lo, span_hi);
    }
    depth = std::clamp(depth, nearest, farthest);
    if (!inside(depth, t)) {
        return kMiss;
    }
    return depth;
}

}  // namespace

RaySpace::RaySpace(const Ray& ray) : ray_(ray) {
    const Vec3& d = ray.direction;
    valid_ = may_hit_anything(ray);
    if (!valid_) {
        return;
    }
    const double ax = std::fabs(d.x);
    const double ay = std::fabs(d.y);
    const double az = std::fabs(d.z);
    kz_ = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    kx_ = (kz_ + 1) % 3;
    ky_ = (kx_ + 1) % 3;
    // |shear| <= 1 because d[kz] is the largest component.
    shear_x_ = d[kx_] / d[kz_];
    shear_y_ = d[ky_] / d[kz_];
    // Scaled by the largest component first, so that the squares neither overflow (components
    // beyond ~1e154) nor underflow (below ~1e-154); unscaled, the grazing limit became infinite or
    // zero and the corner depths 0 or infinite, losing every hit of such a ray. The largest
    // component is |d[kz]|, so d / |d[kz]| is the shears and 1, times d[kz]'s sign: the same bits
    // as three divisions (round to nearest is symmetric: x / -y == -(x / y)), for none.
    const double largest = std::fabs(d[kz_]);
    const double sign = d[kz_] < 0.0 ? -1.0 : 1.0;
    scaled_direction_[kx_] = shear_x_ * sign;
    scaled_direction_[ky_] = shear_y_ * sign;
    scaled_direction_[kz_] = sign;
    scaled_length_ = length(scaled_direction_);
    direction_length_ = largest * scaled_length_;
    grazing_limit_ = kGrazing * direction_length_;
    valid_ = std::isfinite(direction_length_);  // a length beyond DBL_MAX measures no t
}

void RaySpace::project(const Vec3& corner, double& x, double& y) const {
    switch (kz_) {
        case 0:
            project_dropping<0>(corner, x, y);
            break;
        case 1:
            project_dropping<1>(corner, x, y);
            break;
        default:
            project_dropping<2>(corner, x, y);
    }
}

int edge_sign(double xa, double ya, double xb, double yb) {
    const double left = xa * yb;
    const double right = ya * xb;
    const double e = left - right;  // swapping a and b negates this exactly
    const double magnitude = std::fabs(left) + std::fabs(right);
    const double bound = kEdgeErrorBound * magnitude;
    if (magnitude >= kSmallestTrusted && magnitude < HUGE_VAL) {
        if (e > bound) {
            return 1;
        }
        if (e < -bound) {
            return -1;
        }
    }
    if (std::isnan(xa) || std::isnan(ya) || std::isnan(xb) || std::isnan(yb)) {
        return 0;
    }
    return exact_edge_sign(xa, ya, xb, yb);
}

int winding_number(const RaySpace& space, std::span<const Vec3> corners) {
    return winding_of(space, static_cast<std::uint32_t>(corners.size()),
                      [&](std::uint32_t k) -> const Vec3& { return corners[k]; });
}

int winding_number(const RaySpace& space, const PolygonView& polygon) {
    return winding_of(space, polygon.corner_count(),
                      [&](std::uint32_t k) -> const Vec3& { return polygon.corner(k); });
}

bool ray_passes_through(const RaySpace& space, std::span<const Vec3> corners) {
    return winding_number(space, corners) != 0;
}

std::optional<double> plane_hit(const Ray& ray, const Vec3& point, const Vec3& normal) {
    const double denominator = dot(normal, ray.direction);
    if (denominator == 0.0 || !std::isfinite(denominator)) {
        return std::nullopt;
    }
    const double t = dot(normal, point - ray.origin) / denominator;
    if (!std::isfinite(t)) {
        return std::nullopt;
    }
    return t;
}

double polygon_hit_or_nan(const Ray& ray, std::span<const Vec3> corners, const Vec3& normal,
                          Interval t) {
    return hit_of(
        RaySpace(ray), normal, static_cast<std::uint32_t>(corners.size()),
        [&](std::uint32_t k) -> const Vec3& { return corners[k]; }, t);
}

double polygon_hit_or_nan(const RaySpace& space, const PolygonView& polygon, Interval t) {
    return hit_of(
        space, polygon.normal, polygon.corner_count(),
        [&](std::uint32_t k) -> const Vec3& { return polygon.corner(k); }, t);
}

}  // namespace rt
