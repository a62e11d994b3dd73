#include "support/scene_builder.h"

#include <cmath>
#include <numbers>

namespace rt::test {

SceneBuilder::SceneBuilder() {
    scene_.source_files.push_back("built-in-test");
    scene_.attributes.resize(1);
    scene_.surfaces.resize(1);
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

void SceneBuilder::smooth_vertex_normals() {
    std::vector<Vec3> sums(scene_.positions.size());
    for (Polygon& p : scene_.polygons) {
        p.smooth = true;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            sums[scene_.corners[p.first_corner + k]] += p.normal;
        }
    }
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const double len = length(sums[i]);
        scene_.vertex_normals[i] = len > 0.0 ? sums[i] / len : Vec3{};
    }
}

namespace {

// A quad a b c d (counter-clockwise seen from outside), whole or as two triangles.
void add_quad(SceneBuilder& b, const Vec3& a, const Vec3& c1, const Vec3& c2, const Vec3& c3,
              const Vec3& outward, bool triangles) {
    if (triangles) {
        b.add_polygon({a, c1, c2}, outward);
        b.add_polygon({a, c2, c3}, outward);
    } else {
        b.add_polygon({a, c1, c2, c3}, outward);
    }
}

}  // namespace

Scene make_box(const Vec3& lo, const Vec3& hi, bool triangles) {
    SceneBuilder b;
    const auto corner = [&](int i) {
        return Vec3{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    };
    add_quad(b, corner(0), corner(2), corner(3), corner(1), {0, 0, -1}, triangles);
    add_quad(b, corner(4), corner(5), corner(7), corner(6), {0, 0, 1}, triangles);
    add_quad(b, corner(0), corner(1), corner(5), corner(4), {0, -1, 0}, triangles);
    add_quad(b, corner(2), corner(6), corner(7), corner(3), {0, 1, 0}, triangles);
    add_quad(b, corner(0), corner(4), corner(6), corner(2), {-1, 0, 0}, triangles);
    add_quad(b, corner(1), corner(3), corner(7), corner(5), {1, 0, 0}, triangles);
    return std::move(b.scene());
}

Scene make_sphere(const Vec3& centre, double radius, int stacks, int slices, bool triangles) {
    // One table of positions, so every shared corner is the same Vec3 bits (and the poles are
    // single points).
    std::vector<std::vector<Vec3>> ring(static_cast<std::size_t>(stacks + 1));
    for (int i = 0; i <= stacks; ++i) {
        const double theta = std::numbers::pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / slices;
            const bool pole = i == 0 || i == stacks;
            const double s = pole ? 0.0 : std::sin(theta);
            const double c = i == 0 ? 1.0 : (i == stacks ? -1.0 : std::cos(theta));
            ring[i].push_back(centre + Vec3{s * std::cos(phi), c, s * std::sin(phi)} * radius);
        }
    }
    SceneBuilder b;
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const int k = (j + 1) % slices;
            const Vec3 &a = ring[i][j], &a2 = ring[i][k], &d = ring[i + 1][j], &d2 = ring[i + 1][k];
            const Vec3 outward = (a + a2 + d + d2) * 0.25 - centre;
            if (i == 0) {
                b.add_polygon({a, d2, d}, outward);
            } else if (i == stacks - 1) {
                b.add_polygon({a, a2, d}, outward);
            } else {
                add_quad(b, a, a2, d2, d, outward, triangles);
            }
        }
    }
    return std::move(b.scene());
}

Scene make_fan(int count, double radius) {
    SceneBuilder b;
    std::vector<Vec3> rim;
    for (int j = 0; j < count; ++j) {
        const double phi = 2.0 * std::numbers::pi * j / count;
        rim.push_back(Vec3{std::cos(phi), std::sin(phi), 0.0} * radius);
    }
    for (int j = 0; j < count; ++j) {
        b.add_polygon({Vec3{}, rim[j], rim[(j + 1) % count]}, {0, 0, 1});
    }
    return std::move(b.scene());
}

}  // namespace rt::test
