// The exact test of a leaf packet's lane, shared by the single-ray and the packet walks: a
// triangle's corners come from the packet's copy of its indices (one memory access fewer than
// Scene::polygon_view, the same arithmetic); other polygons are read from the scene.
#pragma once

#include <cstdint>
#include <optional>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/geometry/ray_polygon.h"
#include "rt/scene/scene.h"

namespace rt::bvh {

inline std::optional<double> exact_hit(const RaySpace& space, const Scene& scene,
                                       const TrianglePacket& packet, int lane, std::uint32_t id,
                                       Interval t) {
    if (packet.position[0][lane] != kNotTriangle) {
        const std::uint32_t ids[3] = {packet.position[0][lane], packet.position[1][lane],
                                      packet.position[2][lane]};
        return intersect_polygon(space,
                                 PolygonView{scene.positions, ids, scene.polygons[id].normal}, t);
    }
    return intersect_polygon(space, scene.polygon_view(id), t);
}

}  // namespace rt::bvh
