#include "one_polygon_scene.h"

#include <cmath>
#include <numbers>
#include <random>

namespace rt::bench {

Scene regular_polygon_scene(int corners) {
    Scene scene;
    scene.attributes.resize(1);
    Polygon polygon;
    polygon.corner_count = static_cast<std::uint32_t>(corners);
    polygon.normal = {0, 0, 1};
    for (int k = 0; k < corners; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / corners;
        scene.positions.push_back({std::cos(phi), std::sin(phi), 0.0});
        scene.corners.push_back(static_cast<std::uint32_t>(k));
    }
    scene.polygons.push_back(polygon);
    return scene;
}

std::vector<Ray> rays_around_unit_polygon(int count) {
    std::mt19937_64 random(2024);
    std::uniform_real_distribution<double> across(-1.2, 1.2);
    std::uniform_real_distribution<double> above(2.0, 6.0);
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const Vec3 origin{across(random) * 3.0, across(random) * 3.0, above(random)};
        const Vec3 target{across(random), across(random), 0.0};
        rays.push_back({origin, target - origin});
    }
    return rays;
}

}  // namespace rt::bench
