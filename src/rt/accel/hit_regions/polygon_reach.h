// Where the hit points a polygon can report may lie: the ground truth that keeps exit culling and
// the z-buffer conservative. The ray-polygon test (geometry/ray_polygon.h) decides hit or miss by
// the ray's LINE passing through the polygon, and reports the t of the polygon's plane (or, for a
// ray within 1e-6 of the plane, that t clamped to the corners' depths). So a reported hit point
// is not always on the polygon: a warped (non-planar) polygon puts it up to
// distance-from-the-plane / |cos| away, and a grazing ray up to the polygon's diameter away
// along the ray. polygon_reach() bounds both, so a table built from it never misses a hit.
#pragma once

#include <cstdint>

#include "rt/core/bounds.h"
#include "rt/scene/scene.h"

namespace rt {

/// The regions that hold every hit point the polygon can report for the rays considered.
struct PolygonReach {
    /// Hit points of rays more than kGrazingCosine away from edge-on (the plane's t): within
    /// the box, and within slab_half of the plane.
    Box3 box;
    /// Hit points of rays within kGrazingCosine of edge-on (t clamped to the corners' depths);
    /// empty when no ray considered is that close. Within grazing_slab_half of the plane.
    Box3 grazing_box;
    Vec3 plane_point;
    Vec3 normal;  ///< unit; zero when the polygon has no usable normal
    double slab_half = Box3::kInfinity;
    double grazing_slab_half = Box3::kInfinity;
    /// The |cos| with `normal` at or below which a ray is grazing: kGrazingCosine for a unit
    /// scene normal, 1 (every ray) without a usable one.
    double grazing_cosine = 1.0;

    /// Both boxes together.
    Box3 all() const {
        Box3 b = box;
        b.add(grazing_box);
        return b;
    }
};

/// The |cos| between a ray and a polygon's plane at or below which the ray-polygon test treats
/// the polygon as seen edge-on (kGrazing in ray_polygon.h), with headroom for rounding.
inline constexpr double kGrazingCosine = 1e-6 * (1.0 + 1e-9);

/// A polygon's plane and how far its corners stray from it, with polygon_reach()'s allowances:
/// the facts every bound on where a line through the polygon can be starts from.
struct PolygonPlane {
    Box3 corners;                 ///< the box of its corners
    double diameter = 0.0;        ///< of that box, with headroom
    double rounding = 0.0;        ///< the allowance for the exact test's rounding at its scale
    bool usable = false;          ///< false for a zero or non-finite normal (every ray grazes it)
    Vec3 normal;                  ///< unit, when usable
    Vec3 point;                   ///< corner 0
    double rho = 0.0;             ///< the corners' largest distance from the plane, plus `rounding`
    double grazing_cosine = 1.0;  ///< as PolygonReach::grazing_cosine
};

/// The plane of scene polygon `id`; `rounding` as for polygon_reach().
PolygonPlane polygon_plane(const Scene& scene, std::uint32_t id, double rounding);

/// The reach of scene polygon `id` for rays whose |cos| with its normal is at least `min_cos`
/// (0 when rays may come from anywhere). `rounding` is an absolute allowance for the rounding of
/// the ray-polygon test itself: at least 1e-13 times the largest distance between a ray origin
/// and a corner, and the largest |coordinate|, concerned.
PolygonReach polygon_reach(const Scene& scene, std::uint32_t id, double min_cos, double rounding);

/// A lower bound on |cos| between polygon `id`'s unit normal and any line that passes through
/// its convex hull and within `slack` of `point` (0 if such a line can lie in its plane). For
/// the z-buffer, whose rays all pass (within rounding) through the eye.
double min_cosine_through(const Scene& scene, std::uint32_t id, const Vec3& point, double slack);

/// Whether the box can contain hit points of the reach's `box` (its slab meets it)...
bool slab_meets_box(const PolygonReach& reach, const Box3& box);
/// ... and of its `grazing_box`.
bool grazing_slab_meets_box(const PolygonReach& reach, const Box3& box);

}  // namespace rt
