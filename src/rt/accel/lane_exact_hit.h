// The exact test of a packet lane, shared by the BVH's leaf packets and the voxel methods' cell
// packets: a triangle's corners come from the packet's copy of their indices into
// Scene::positions (lane_corners.h), so its positions are read at once (alongside the polygon's
// normal) instead of after the polygon's record and then its corner list, two dependent reads that
// miss the cache on big meshes. The same PolygonView Scene::polygon_view gives, so the same
// arithmetic and the same answer; other polygons are read from the scene. Also the one rule every
// method and brute force apply before any exact test: a ray skips the polygon it leaves
// (leaves_polygon), asked at each call site before the ray's RaySpace is made, so a ray whose only
// candidate is that polygon never makes one.
#pragma once

#include <cstdint>
#include <optional>

#include "rt/accel/hit.h"
#include "rt/accel/lane_corners.h"
#include "rt/geometry/ray_polygon.h"
#include "rt/scene/scene.h"

namespace rt {

/// Whether polygon `id` is left out of the ray's exact tests: the polygon it leaves
/// (Ray::leaves). Every method and brute force ask this before an exact test, and count no test
/// for it.
inline bool leaves_polygon(const Ray& ray, std::uint32_t id) {
    return id == ray.leaves;
}

/// Offers polygon `id`'s exact hit on the ray of `space` to `nearest`, as brute force finds it:
/// nothing for the polygon the ray leaves, one test counted in `tests` otherwise, asked within
/// nearest's search interval, so that the t is brute force's and an equal t goes to the lowest id
/// whatever the order of the offers (the guards', a tile's nearest first).
inline void offer_exact_hit(const Scene& scene, const RaySpace& space, std::uint32_t id,
                            ClosestHitSoFar& nearest, std::uint64_t& tests) {
    if (leaves_polygon(space.ray(), id)) {
        return;
    }
    ++tests;
    if (const std::optional<double> hit =
            intersect_polygon(space, scene.polygon_view(id), nearest.search_interval())) {
        nearest.offer(*hit, id);
    }
}

/// intersect_polygon for polygon `id` in `lane` of a packet whose `position` holds a triangle
/// polygon's corner indices in its Scene::corners order.
inline std::optional<double> lane_exact_hit(const RaySpace& space, const Scene& scene,
                                            const LaneCorners& position, int lane, std::uint32_t id,
                                            Interval t) {
    if (position.is_triangle(lane)) {
        const std::uint32_t ids[3] = {position.corner(0, lane), position.corner(1, lane),
                                      position.corner(2, lane)};
        return intersect_polygon(space,
                                 PolygonView{scene.positions, ids, scene.polygons[id].normal}, t);
    }
    return intersect_polygon(space, scene.polygon_view(id), t);
}

/// lane_exact_hit's answer, without the ray's RaySpace, for a lane whose fan triangle the float
/// pre-filter found the ray's line surely crossing (float_ray.cpp, part 4) when that triangle is
/// the whole polygon: the exact winding number is then nonzero, and plane_decides_crossing gives
/// the rest. Returns false, deciding nothing, for a polygon of more corners (its fan triangle
/// says nothing of its winding number) and where plane_decides_crossing does not decide.
inline bool lane_sure_hit(const Ray& ray, const Scene& scene, const LaneCorners& position, int lane,
                          std::uint32_t id, Interval t, std::optional<double>& hit) {
    const Polygon& polygon = scene.polygons[id];
    if (position.is_triangle(lane)) {
        return plane_decides_crossing(ray, polygon.normal, scene.positions[position.first[lane]], t,
                                      hit);
    }
    return polygon.corner_count == 3 &&
           plane_decides_crossing(ray, polygon.normal,
                                  scene.positions[scene.corners[polygon.first_corner]], t, hit);
}

/// plane_certainly_missed for polygon `id`, read from the scene: asked before the ray's RaySpace
/// is made (once it is, the exact test asks the same at once), and only of a ray leaving a
/// polygon. Such rays (reflections, shadow feelers) meet the plane of coplanar neighbours at
/// their start, and a feeler ends on its light's polygon: both fail here, and often they are
/// the ray's only candidates. A ray from the eye (and the lab's rays) rarely has such a candidate,
/// and would pay for the question on its first one with nothing back.
inline bool polygon_plane_certainly_missed(const Ray& ray, const Scene& scene, std::uint32_t id,
                                           Interval t) {
    if (ray.leaves == kLeavesNoPolygon) {
        return false;
    }
    const Polygon& polygon = scene.polygons[id];
    if (polygon.corner_count < 3) {
        return true;  // the exact test's answer too, and it reads no corner
    }
    return plane_certainly_missed(ray, polygon.normal,
                                  scene.positions[scene.corners[polygon.first_corner]], t);
}

/// The same for polygon `id` in `lane` of such a packet, its first corner read from the packet.
inline bool lane_plane_certainly_missed(const Ray& ray, const Scene& scene,
                                        const LaneCorners& position, int lane, std::uint32_t id,
                                        Interval t) {
    if (ray.leaves == kLeavesNoPolygon) {
        return false;
    }
    if (!position.is_triangle(lane)) {
        return polygon_plane_certainly_missed(ray, scene, id, t);
    }
    return plane_certainly_missed(ray, scene.polygons[id].normal,
                                  scene.positions[position.first[lane]], t);
}

}  // namespace rt
