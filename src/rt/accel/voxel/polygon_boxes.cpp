#include "rt/accel/voxel/polygon_boxes.h"

#include <cmath>

namespace rt {

LineProbe::LineProbe(const Ray& ray) : origin(ray.origin) {
    for (int a = 0; a < 3; ++a) {
        parallel[a] = ray.direction[a] == 0.0;
        inverse[a] = parallel[a] ? 0.0 : 1.0 / ray.direction[a];
        any_parallel = any_parallel || parallel[a];
    }
}

PolygonBoxes::PolygonBoxes(const Scene& scene, double growth) {
    boxes_.reserve(6 * scene.polygons.size());
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Box box = polygon_bounds(scene, id).padded(growth);
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
