#include "rt/shading/lights.h"

#include "rt/scene/textured_point.h"

namespace rt {

namespace {

Vec3 polygon_centre(const Scene& scene, const Polygon& p) {
    Vec3 sum;
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        sum += scene.corner_position(p, k);
    }
    return sum / static_cast<double>(p.corner_count);
}

}  // namespace

std::vector<PointLight> collect_point_lights(const Scene& scene, int lghtick, bool share) {
    std::vector<PointLight> lights;
    if (lghtick != 1 && lghtick != 2) {
        return lights;
    }
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        const Attribute& a = scene.attribute_of(p);
        if (!a.is_emissive()) {
            continue;
        }
        // A texture-mapped emitter gives the light of its colour at its centre.
        const Vec3 centre = polygon_centre(scene, p);
        const Rgb total = surface_color(scene, id, centre) * a.emission;
        if (lghtick == 2) {
            lights.push_back({centre, total, id});
            continue;
        }
        const Rgb each = share ? total * (1.0 / static_cast<double>(p.corner_count)) : total;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            lights.push_back({scene.corner_position(p, k), each, id});
        }
    }
    return lights;
}

}  // namespace rt
