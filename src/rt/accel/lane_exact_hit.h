// The exact test of a packet lane, shared by the BVH's leaf packets and the voxel methods' cell
// packets: a triangle's corners come from the packet's copy of their indices into
// Scene::positions, so its positions are read at once (alongside the polygon's normal) instead
// of after the polygon's record and then its corner list, two dependent reads that miss the cache
// on big meshes. The same PolygonView Scene::polygon_view gives, so the same arithmetic and the
// same answer; other polygons are read from the scene. Also the one rule every method and brute
// force apply before any exact test: a ray skips the polygon it leaves (leaves_polygon), asked
// at each call site before the ray's RaySpace is made, so a ray whose only candidate is that
// polygon never makes one.
#pragma once

#include <cstdint>
#include <optional>

#include "rt/geometry/ray_polygon.h"
#include "rt/scene/scene.h"

namespace rt {

/// Whether polygon `id` is left out of the ray's exact tests: the polygon it leaves
/// (Ray::leaves). Every method and brute force ask this before an exact test, and count no test
/// for it.
inline bool leaves_polygon(const Ray& ray, std::uint32_t id) {
    return id == ray.leaves;
}

/// In a packet's `position[0][lane]`: the lane's polygon is not a triangle (or the lane is
/// unused), and the exact test reads the Scene.
inline constexpr std::uint32_t kNotTriangle = 0xffffffffu;

/// intersect_polygon for polygon `id` in `lane` of a packet whose `position` ([vertex][lane])
/// holds a triangle polygon's corner indices in its Scene::corners order.
inline std::optional<double> lane_exact_hit(const RaySpace& space, const Scene& scene,
                                            const std::uint32_t (&position)[3][4], int lane,
                                            std::uint32_t id, Interval t) {
    if (position[0][lane] != kNotTriangle) {
        const std::uint32_t ids[3] = {position[0][lane], position[1][lane], position[2][lane]};
        return intersect_polygon(space,
                                 PolygonView{scene.positions, ids, scene.polygons[id].normal}, t);
    }
    return intersect_polygon(space, scene.polygon_view(id), t);
}

}  // namespace rt
