// Welding a model's vertices (model_mesh_check.h) against a std::map worked out here: thousands of
// positions each written several times in shuffled order, +0 and -0 alike, loops with repeated
// corners and loops through one corner twice, with and without normals. The welded mesh must be
// the first vertex at each position, in order, and every loop mapped, shortened or skipped as the
// map says.
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/model_mesh_check.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

using Key = std::array<double, 3>;

Key key_of(const Vec3& p) {
    return {p.x + 0.0, p.y + 0.0, p.z + 0.0};  // -0 and +0 are one position
}

struct Expected {
    std::vector<Vec3> vertices;
    std::vector<std::vector<std::uint32_t>> loops;
    std::vector<std::vector<Vec3>> normals;
    std::vector<long> numbers;
};

// The weld worked out with a map: first vertices in order, loops mapped, a corner equal to the
// one before it (cyclically) dropped, a loop still through one corner twice skipped.
Expected weld_by_map(const SurfaceMesh& mesh) {
    Expected e;
    std::map<Key, std::uint32_t> place;
    std::vector<std::uint32_t> welded;
    for (const Vec3& v : mesh.vertices) {
        const auto [at, fresh] =
            place.emplace(key_of(v), static_cast<std::uint32_t>(e.vertices.size()));
        if (fresh) {
            e.vertices.push_back(v);
        }
        welded.push_back(at->second);
    }
    for (const MeshPolygon& p : mesh.polygons) {
        std::vector<std::uint32_t> loop;
        std::vector<Vec3> normals;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const std::uint32_t c = welded[mesh.corners[p.first_corner + k]];
            if (!loop.empty() && loop.back() == c) {
                continue;
            }
            loop.push_back(c);
            if (!mesh.corner_normals.empty()) {
                normals.push_back(mesh.corner_normals[p.first_corner + k]);
            }
        }
        while (loop.size() > 1 && loop.back() == loop.front()) {
            loop.pop_back();
            if (!normals.empty()) {
                normals.pop_back();
            }
        }
        std::vector<std::uint32_t> sorted = loop;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
            continue;
        }
        e.loops.push_back(loop);
        e.normals.push_back(normals);
        e.numbers.push_back(p.number);
    }
    return e;
}

SurfaceMesh shuffled_mesh(std::uint64_t seed, bool with_normals) {
    std::mt19937_64 random(seed);
    std::uniform_int_distribution<int> coordinate(-3, 3);
    std::vector<Vec3> positions;
    positions.reserve(3000);
    for (int k = 0; k < 3000; ++k) {
        positions.push_back({coordinate(random) * 0.5, coordinate(random) * 0.25,
                             static_cast<double>(coordinate(random))});
    }
    SurfaceMesh mesh;
    for (int k = 0; k < 12000; ++k) {
        Vec3 p = positions[random() % positions.size()];
        if (random() % 2 == 0) {  // the same position with its zeros written -0
            p = {p.x == 0.0 ? -0.0 : p.x, p.y == 0.0 ? -0.0 : p.y, p.z == 0.0 ? -0.0 : p.z};
        }
        mesh.vertices.push_back(p);
    }
    for (int k = 0; k < 5000; ++k) {
        const int corners = 3 + static_cast<int>(random() % 4);
        std::vector<std::uint32_t> loop;
        loop.reserve(static_cast<std::size_t>(corners) + 1);
        for (int c = 0; c < corners; ++c) {
            loop.push_back(static_cast<std::uint32_t>(random() % mesh.vertices.size()));
        }
        if (k % 5 == 0) {
            loop.push_back(loop.back());  // a repeated corner
        }
        MeshPolygon polygon;
        polygon.number = k;
        mesh.add_polygon(polygon, loop);
        if (with_normals) {
            for (std::size_t c = 0; c < loop.size(); ++c) {
                mesh.corner_normals.push_back({static_cast<double>(k), static_cast<double>(c), 1});
            }
        }
    }
    return mesh;
}

TEST(WeldVertices, GivesWhatAMapGives) {
    for (const bool with_normals : {false, true}) {
        SurfaceMesh mesh = shuffled_mesh(7, with_normals);
        const Expected expected = weld_by_map(mesh);
        Diagnostics diagnostics;
        weld_vertices(mesh, "m.obj", diagnostics);
        ASSERT_EQ(mesh.vertices.size(), expected.vertices.size());
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            EXPECT_EQ(key_of(mesh.vertices[v]), key_of(expected.vertices[v])) << v;
        }
        ASSERT_EQ(mesh.polygons.size(), expected.loops.size());
        EXPECT_LT(mesh.polygons.size(), 5000u) << "some loops pass through a corner twice";
        std::uint32_t next_corner = 0;
        for (std::size_t i = 0; i < mesh.polygons.size(); ++i) {
            const MeshPolygon& p = mesh.polygons[i];
            EXPECT_EQ(p.number, expected.numbers[i]);
            EXPECT_EQ(p.first_corner, next_corner);
            const std::vector<std::uint32_t> loop(
                mesh.corners.begin() + p.first_corner,
                mesh.corners.begin() + p.first_corner + p.corner_count);
            EXPECT_EQ(loop, expected.loops[i]) << "polygon " << p.number;
            if (with_normals) {
                for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                    EXPECT_EQ(mesh.corner_normals[p.first_corner + k].y, expected.normals[i][k].y);
                }
            }
            next_corner += p.corner_count;
        }
        EXPECT_EQ(mesh.corners.size(), next_corner);
        EXPECT_EQ(mesh.corner_normals.size(), with_normals ? next_corner : 0u);
        EXPECT_FALSE(diagnostics.warnings().empty());
    }
}

}  // namespace
}  // namespace rt
