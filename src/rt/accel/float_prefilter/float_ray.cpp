// Why the float tests never lose a hit the exact test would find.
//
// Let m = S + |O| (S the largest |coordinate| of any box, |O| the largest |coordinate| of the
// origin) and u = 2^-24, float's rounding unit. Every bound below is taken with a factor of at
// least 2 to spare; kRelativeSlack = 2^-20 = 16u. Each bound counts one rounding per operation;
// where a multiply and an add are fused into one step (fused_float8.h), that step rounds once
// instead of twice, so the same bound holds.
//
// 1. Where the exact test can hit. intersect_polygon decides by the winding number of the ray
//    around the polygon's corners projected in double (RaySpace::project), each projected
//    coordinate within about 2^-49 m of the real projection. A nonzero winding number means the
//    ray passes through one of the polygon's fan triangles as projected, so within 2^-49 m of
//    that real triangle: the ray's line passes within 2^-49 m of the polygon's box.
//    The t it returns is either the plane's (polygon normal, |cos| above RaySpace's grazing
//    limit of 1e-6) or a grazing depth. The plane's point lies within 2^-49 m / 1e-6 < 2^-28 m
//    of the polygon, so of its box, as long as the plane is the polygon's (non-planar corners
//    are covered by inflating the box, polygon_references.cpp); its t's own rounding, at most
//    2^-52 * 1e6 * m / |D'| < 2^-31 m / |D'|, moves it less than 2^-31 m. The grazing depth is
//    kept where the line is within 2^-39 m of the corners' box (ray_polygon.cpp, part 4). So
//    the hit's point is within 2^-27 m of the box on every axis, and a box is culled only when
//    its line misses it or meets it only outside [t_min, t_max] (slab test, below), with margins
//    that swallow that distance and the rounding of the double and float computations.
//
// 2. Slab test. With o = float(O) (error <= u|O|), inverse = float(1/D') (relative error <= u),
//    plane p a float, a plane's t is taken in one of two forms, against the real (p - O) / D':
//    - a ray's own test (bvh/box_test.h), two float operations: p * inverse - offset, the offset
//      o * inverse + slab_margin (near planes) or o * inverse - slab_margin (far planes), rounded
//      in float once a ray. Off from the real t -+ slab_margin by at most 3u |t| (the inverse's
//      and the subtraction's relative roundings) plus u (|p| + 3|O|) |1/D'| <= 3u m |1/D'| (the
//      roundings of the two products and of the offset's sum, and the origin's rounding divided
//      by D');
//    - a packet's tests (bvh/packet_node_tests.h), lane by lane and as a bound over its lanes
//      (each operation is monotone in each operand): (p - o) * inverse -+ slab_margin, off from
//      the real t -+ slab_margin by at most 3u |t| + u |O| |1/D'| (relative roundings, and the
//      origin's rounding divided by D').
//    slab_margin[k] = 2^-20 m |inverse[k]| = 16u m |inverse[k]| covers the 3u m |1/D'| and the
//    2^-27 m of part 1 (u/8 m |1/D'| in t) five times over. The relative 3u |t| is bounded by
//    the same measure: a plane is within S of the origin of coordinates and the ray's origin
//    within |O|, so a plane's |t| = |p - O| |1/D'| <= m |1/D'| (an empty slot's infinite plane
//    gives an infinite t, no NaN, as the inverse is never zero). So the whole error, 6u m |1/D'| in
//    the ray's own test and 4u m |1/D'| in a packet's, and part 1's distance are covered by
//    slab_margin alone, at least two and a half times over, and nothing more widens the interval
//    (two steps fewer on the chain from a node to the next). A zero direction component is
//    clamped to 2^-60 times the largest: the pretend ray drifts by 2^-60 t, below 2^-57 m for any
//    t at which it is still within the scene, far inside the margin (and p * inverse stays below
//    2^100, a finite float). The interval, so taken, holds the scaled t of every hit the exact
//    test can find in the box, and t_min and t_max are rounded outward (scaled_down, scaled_up)
//    before they are compared.
//
// 3. Triangle pre-filter. The float projection of a corner (stored rounded to nearest) differs
//    from the double one by at most eps = 2^-20 m (about 8u m: the corner's and origin's
//    rounding, the shear's, three operations). The edge function E = x_a y_b - y_a x_b computed
//    in float then differs from the double one by at most 4 eps L + 4 eps^2 + 4u L^2, L the
//    largest |coordinate| of the triangle's projected corners. If the double E of the three
//    edges had strictly mixed signs, the origin would lie outside the triangle as projected in
//    double, and so would the exact test's displaced ray (which is within an infinitesimal of
//    the origin): rejecting needs the float E's to have mixed signs beyond
//    8 eps L + 2^-20 L^2 + 8 eps^2.
//
// 4. Sure crossings. The same bound read the other way: when every float E is above that margin
//    (or every one below minus it), every double E is strictly positive (or negative), so the
//    origin lies strictly inside the triangle as projected in double, and so does the exact
//    test's displaced ray: for a polygon that is this triangle, the exact winding number is
//    nonzero. The exact test's answer is then its plane's t alone, when the plane is met away
//    from edge-on (plane_decides_crossing, geometry/ray_polygon.h), and the walks take it so
//    without the ray's RaySpace. Both the BVH's leaves and its packets' lanes ask it
//    (bvh/packet_pair_prefilter.h); a fan triangle of a polygon of more corners says nothing of
//    the polygon's winding number and is always tested exactly.
//
// The set-up that computes these bounds is in float_ray_inl.h.
#include "rt/accel/float_prefilter/float_ray.h"

namespace rt {

// Out of line: measured inline in the voxel methods' walks, their rates moved by 0.95-1.03 and
// gained nothing (docs/lab/inline-setup-2026-12-06.md).
FloatRay::FloatRay(const Ray& ray, double scene_scale, TrianglesOnly) {
    float_ray_detail::set_up<float_ray_detail::Parts::TrianglesOnly>(*this, ray, scene_scale);
}

}  // namespace rt
