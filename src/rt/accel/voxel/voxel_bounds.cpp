#include "rt/accel/voxel/voxel_bounds.h"

#include <algorithm>
#include <cmath>

namespace rt {

std::vector<float> grown_polygon_boxes(const Scene& scene, double growth) {
    std::vector<float> boxes(6 * scene.polygons.size());
    for (std::size_t id = 0; id < scene.polygons.size(); ++id) {
        const Box3 b = polygon_bounds(scene, static_cast<std::uint32_t>(id)).grown(growth);
        for (int a = 0; a < 3; ++a) {
            boxes[6 * id + a] = std::nextafter(static_cast<float>(b.lo[a]), -HUGE_VALF);
            boxes[6 * id + 3 + a] = std::nextafter(static_cast<float>(b.hi[a]), HUGE_VALF);
        }
    }
    return boxes;
}

void append_voxel_bounds(const std::vector<float>& grown_boxes, std::span<const std::uint32_t> ids,
                         const Box3& voxel, double growth, std::vector<std::uint32_t>& out) {
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF};
    float hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
    for (const std::uint32_t id : ids) {
        const float* b = grown_boxes.data() + 6 * static_cast<std::size_t>(id);
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b[a]);
            hi[a] = std::max(hi[a], b[3 + a]);
        }
    }
    // Clipped to the room, itself rounded outward: the result still holds every polygon's part
    // within the voxel grown by the fudge.
    const Box3 room = voxel.grown(2.0 * growth);
    for (int a = 0; a < 3; ++a) {
        const float room_lo = std::nextafter(static_cast<float>(room.lo[a]), -HUGE_VALF);
        out.push_back(std::bit_cast<std::uint32_t>(std::max(lo[a], room_lo)));
    }
    for (int a = 0; a < 3; ++a) {
        const float room_hi = std::nextafter(static_cast<float>(room.hi[a]), HUGE_VALF);
        out.push_back(std::bit_cast<std::uint32_t>(std::min(hi[a], room_hi)));
    }
}

}  // namespace rt
