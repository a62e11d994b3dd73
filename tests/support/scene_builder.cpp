#include "support/scene_builder.h"

namespace rt::test {

SceneBuilder::SceneBuilder() {
    scene_.source_files.push_back("built-in-test");
    scene_.attributes.resize(1);
    scene_.view.width = 16;
    scene_.view.height = 16;
    scene_.view.window = {0, 0, 15, 15};
    scene_.view.eye = {0, 0, -10};
    scene_.header.maxdepth = 1;
}

Vec3 newell_normal(const std::vector<Vec3>& corners) {
    Vec3 n;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const Vec3& a = corners[i];
        const Vec3& b = corners[(i + 1) % corners.size()];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    const double len = length(n);
    return len > 0.0 ? n / len : n;
}

std::uint32_t SceneBuilder::position_of(const Vec3& p) {
    for (std::uint32_t i = 0; i < scene_.positions.size(); ++i) {
        if (scene_.positions[i] == p) {
            return i;
        }
    }
    scene_.positions.push_back(p);
    scene_.vertex_normals.push_back({});
    return static_cast<std::uint32_t>(scene_.positions.size() - 1);
}

std::uint32_t SceneBuilder::add_polygon(const std::vector<Vec3>& corners, const Vec3& outward,
                                        std::uint32_t attribute) {
    Polygon p;
    p.first_corner = static_cast<std::uint32_t>(scene_.corners.size());
    p.corner_count = static_cast<std::uint32_t>(corners.size());
    for (const Vec3& c : corners) {
        scene_.corners.push_back(position_of(c));
    }
    p.normal = newell_normal(corners);
    if (dot(p.normal, outward) < 0.0) {
        p.normal = -p.normal;
    }
    p.attribute = attribute;
    scene_.polygons.push_back(p);
    scene_.polygon_origin.push_back({0, static_cast<std::uint32_t>(scene_.polygons.size())});
    return static_cast<std::uint32_t>(scene_.polygons.size() - 1);
}

}  // namespace rt::test
