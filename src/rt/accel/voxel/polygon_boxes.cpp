#include "rt/accel/voxel/polygon_boxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

// Takes a triangle's corners, as floats rounded to nearest, into the scale.
void PolygonBoxes::measure_triangle(const Scene& scene, std::uint32_t id) {
    const Polygon& p = scene.polygons[id];
    double size = 0.0;
    for (std::uint32_t v = 0; v < 3 && p.corner_count == 3; ++v) {
        const Vec3 c = scene.corner_position(p, v);
        for (int a = 0; a < 3; ++a) {
            size = std::max(size, std::fabs(static_cast<double>(static_cast<float>(c[a]))));
        }
    }
    if (p.corner_count == 3 && size < HUGE_VAL) {  // also false for a NaN
        scale_ = std::max(scale_, size);
    }
}

PolygonBoxes::PolygonBoxes(const Scene& scene, double growth) {
    boxes_.reserve(6 * scene.polygons.size());
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        measure_triangle(scene, id);
        const Box3 box = polygon_bounds(scene, id).grown(growth);
        // Rounded to float outward, so the float box holds the double one.
        for (int a = 0; a < 3; ++a) {
            boxes_.push_back(std::nextafter(static_cast<float>(box.lo[a]), -HUGE_VALF));
        }
        for (int a = 0; a < 3; ++a) {
            boxes_.push_back(std::nextafter(static_cast<float>(box.hi[a]), HUGE_VALF));
        }
    }
}

}  // namespace rt
