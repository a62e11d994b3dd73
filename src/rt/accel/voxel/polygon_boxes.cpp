#include "rt/accel/voxel/polygon_boxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rt/accel/float_prefilter/triangle_prefilter.h"

namespace rt {

// Appends the polygon's corners as floats rounded to nearest (as the BVH's packets keep them), or
// nine NaN for a polygon that is not a triangle or has a corner beyond float's range.
void PolygonBoxes::keep_triangle(const Scene& scene, std::uint32_t id) {
    const Polygon& p = scene.polygons[id];
    float corners[9];
    double size = 0.0;
    for (std::uint32_t v = 0; v < 3 && p.corner_count == 3; ++v) {
        const Vec3 c = scene.corner_position(p, v);
        for (int a = 0; a < 3; ++a) {
            corners[3 * v + a] = static_cast<float>(c[a]);
            size = std::max(size, std::fabs(static_cast<double>(corners[3 * v + a])));
        }
    }
    if (p.corner_count != 3 || !(size < HUGE_VAL)) {  // also false for a NaN
        corners_.insert(corners_.end(), 9, std::numeric_limits<float>::quiet_NaN());
        return;
    }
    scale_ = std::max(scale_, size);
    corners_.insert(corners_.end(), corners, corners + 9);
}

bool PolygonBoxes::triangle_may_be_hit(TriangleProbe& probe, std::uint32_t polygon) const {
    const float* corners = corners_.data() + 9 * static_cast<std::size_t>(polygon);
    if (std::isnan(corners[0])) {
        return true;
    }
    const FloatRay& ray = probe.get();
    return !ray.usable || triangle_candidate(corners, ray);
}

LineProbe::LineProbe(const Ray& ray) : origin(ray.origin) {
    for (int a = 0; a < 3; ++a) {
        parallel[a] = ray.direction[a] == 0.0;
        inverse[a] = parallel[a] ? 0.0 : 1.0 / ray.direction[a];
        any_parallel = any_parallel || parallel[a];
    }
}

PolygonBoxes::PolygonBoxes(const Scene& scene, double growth) {
    boxes_.reserve(6 * scene.polygons.size());
    corners_.reserve(9 * scene.polygons.size());
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        keep_triangle(scene, id);
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
