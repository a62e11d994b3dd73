#include "support/meshes/generated_meshes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

namespace rt::test {

namespace {

// A fresh scene with one default attribute and surface, so shading code could render it too.
Scene empty_generated_scene(const char* name) {
    Scene scene;
    scene.source_files.push_back(name);
    scene.attributes.resize(1);
    scene.surfaces.resize(1);
    scene.view.eye = {0, 0, -4};
    scene.view.width = 512;
    scene.view.height = 400;
    scene.view.window = {0, 0, 511, 399};
    return scene;
}

// Appends a triangle of existing positions; the normal is the corners' own, turned outward.
// Returns false (adding nothing) for a degenerate triangle.
bool add_triangle(Scene& scene, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                  const Vec3& outward) {
    const Vec3& pa = scene.positions[a];
    Vec3 n = cross(scene.positions[b] - pa, scene.positions[c] - pa);
    const double len = length(n);
    if (!(len > 0.0) || !std::isfinite(len)) {
        return false;
    }
    n = n / len;
    if (dot(n, outward) < 0.0) {
        n = -n;
    }
    Polygon p;
    p.first_corner = static_cast<std::uint32_t>(scene.corners.size());
    p.corner_count = 3;
    p.normal = n;
    scene.corners.insert(scene.corners.end(), {a, b, c});
    scene.polygons.push_back(p);
    scene.polygon_origin.push_back({0, static_cast<std::uint32_t>(scene.polygons.size())});
    return true;
}

}  // namespace

Scene make_tessellated_sphere(std::uint32_t triangles, const Vec3& centre, double radius) {
    // A UV sphere of s stacks and 2s slices has 2 * 2s * (s - 1) triangles, about 4 s^2.
    const int stacks = std::max(2, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
    const int slices = 2 * stacks;
    Scene scene = empty_generated_scene("generated sphere");
    scene.positions.push_back(centre + Vec3{0, radius, 0});  // north pole
    for (int i = 1; i < stacks; ++i) {
        const double theta = std::numbers::pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / slices;
            const Vec3 unit{std::sin(theta) * std::cos(phi), std::cos(theta),
                            std::sin(theta) * std::sin(phi)};
            scene.positions.push_back(centre + unit * radius);
        }
    }
    scene.positions.push_back(centre + Vec3{0, -radius, 0});  // south pole
    const auto south = static_cast<std::uint32_t>(scene.positions.size() - 1);
    const auto at = [&](int ring, int j) {  // ring 1 .. stacks-1
        return static_cast<std::uint32_t>(1 + (ring - 1) * slices + (j % slices));
    };
    scene.polygons.reserve(static_cast<std::size_t>(4) * stacks * stacks);
    for (int j = 0; j < slices; ++j) {
        // Outward is from the centre to the triangle's centroid (times three).
        const auto out = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            add_triangle(
                scene, a, b, c,
                scene.positions[a] + scene.positions[b] + scene.positions[c] - centre * 3.0);
        };
        out(0, at(1, j + 1), at(1, j));
        for (int i = 1; i + 1 < stacks; ++i) {
            out(at(i, j), at(i, j + 1), at(i + 1, j + 1));
            out(at(i, j), at(i + 1, j + 1), at(i + 1, j));
        }
        out(at(stacks - 1, j), at(stacks - 1, j + 1), south);
    }
    scene.vertex_normals.assign(scene.positions.size(), Vec3{});
    scene.view.look = centre;
    scene.view.eye = centre + Vec3{0, 0, -4 * radius};
    return scene;
}

Scene make_triangle_soup(std::uint32_t triangles, std::uint64_t seed) {
    Scene scene = empty_generated_scene("generated soup");
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double size =
        std::pow(static_cast<double>(std::max<std::uint32_t>(triangles, 1)), -1.0 / 3.0);
    scene.positions.reserve(static_cast<std::size_t>(triangles) * 3);
    scene.polygons.reserve(triangles);
    while (scene.polygons.size() < triangles) {
        const Vec3 middle{unit(random), unit(random), unit(random)};
        const auto first = static_cast<std::uint32_t>(scene.positions.size());
        for (int k = 0; k < 3; ++k) {
            const Vec3 offset{unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5};
            const Vec3 p = middle + offset * size;
            scene.positions.push_back(
                {std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0), std::clamp(p.z, 0.0, 1.0)});
        }
        if (!add_triangle(scene, first, first + 1, first + 2, Vec3{0, 0, -1})) {
            scene.positions.resize(first);
        }
    }
    scene.vertex_normals.assign(scene.positions.size(), Vec3{});
    scene.view.look = {0.5, 0.5, 0.5};
    scene.view.eye = {0.5, 0.5, -2.0};
    return scene;
}

void scatter_positions(Scene& scene, std::uint32_t spread, std::uint64_t seed) {
    const std::size_t count = scene.positions.size();
    std::vector<std::uint32_t> slot(count * spread);
    std::iota(slot.begin(), slot.end(), 0u);
    std::mt19937_64 random(seed);
    std::shuffle(slot.begin(), slot.end(), random);
    slot.resize(count);  // slot[i]: where position i goes
    std::vector<Vec3> positions(count * spread, count > 0 ? scene.positions[0] : Vec3{});
    std::vector<Vec3> normals;
    if (!scene.vertex_normals.empty()) {
        normals.assign(positions.size(), scene.vertex_normals[0]);
    }
    for (std::size_t i = 0; i < count; ++i) {
        positions[slot[i]] = scene.positions[i];
        if (!normals.empty()) {
            normals[slot[i]] = scene.vertex_normals[i];
        }
    }
    for (std::uint32_t& corner : scene.corners) {
        corner = slot[corner];
    }
    scene.positions = std::move(positions);
    scene.vertex_normals = std::move(normals);
}

Scene make_cube_sphere(std::uint32_t triangles) {
    const int n = std::max(1, static_cast<int>(std::sqrt(triangles / 12.0)));
    Scene scene = empty_generated_scene("generated cube sphere");
    const auto vertex = [&](int face, int i, int j) {
        const double u = -1.0 + 2.0 * i / n;
        const double v = -1.0 + 2.0 * j / n;
        const int axis = face % 3;
        const double side = face < 3 ? 1.0 : -1.0;
        Vec3 p;
        p[axis] = side;
        p[(axis + 1) % 3] = u * side;
        p[(axis + 2) % 3] = v;
        scene.positions.push_back(normalize(p));
        return static_cast<std::uint32_t>(scene.positions.size() - 1);
    };
    const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        add_triangle(scene, a, b, c, scene.positions[a] + scene.positions[b] + scene.positions[c]);
    };
    scene.polygons.reserve(static_cast<std::size_t>(12) * n * n);
    for (int face = 0; face < 6; ++face) {
        std::vector<std::uint32_t> grid;
        for (int i = 0; i <= n; ++i) {
            for (int j = 0; j <= n; ++j) {
                grid.push_back(vertex(face, i, j));
            }
        }
        const auto at = [&](int i, int j) { return grid[i * (n + 1) + j]; };
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                add(at(i, j), at(i + 1, j), at(i + 1, j + 1));
                add(at(i, j), at(i + 1, j + 1), at(i, j + 1));
            }
        }
    }
    scene.vertex_normals.assign(scene.positions.size(), Vec3{});
    return scene;
}

}  // namespace rt::test
