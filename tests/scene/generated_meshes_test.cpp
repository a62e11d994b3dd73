// The tests' and benchmarks' synthetic meshes: sizes, closure, unit normals, bounds.
#include "support/meshes/generated_meshes.h"

#include <cmath>
#include <map>
#include <utility>

#include <gtest/gtest.h>

namespace rt {
namespace {

void expect_unit_outward_triangles(const Scene& scene) {
    for (const Polygon& p : scene.polygons) {
        ASSERT_EQ(p.corner_count, 3u);
        EXPECT_NEAR(length(p.normal), 1.0, 1e-12);
    }
    EXPECT_EQ(scene.polygon_origin.size(), scene.polygons.size());
    EXPECT_EQ(scene.vertex_normals.size(), scene.positions.size());
}

TEST(GeneratedMeshes, SphereIsClosedWithOutwardNormalsAndAboutTheAskedSize) {
    for (const std::uint32_t asked : {8u, 1000u, 10000u}) {
        const Scene sphere = test::make_tessellated_sphere(asked, {1, 2, 3}, 2.0);
        expect_unit_outward_triangles(sphere);
        EXPECT_NEAR(static_cast<double>(sphere.polygons.size()), asked, 0.1 * asked + 8);
        // Closed: every edge is used once in each direction.
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
        for (const Polygon& p : sphere.polygons) {
            for (std::uint32_t k = 0; k < 3; ++k) {
                ++edges[{sphere.corners[p.first_corner + k],
                         sphere.corners[p.first_corner + (k + 1) % 3]}];
            }
            const Vec3 centroid = (sphere.corner_position(p, 0) + sphere.corner_position(p, 1) +
                                   sphere.corner_position(p, 2)) *
                                  (1.0 / 3.0);
            EXPECT_GT(dot(p.normal, centroid - Vec3{1, 2, 3}), 0.0);
        }
        for (const auto& [edge, count] : edges) {
            EXPECT_EQ(count, 1);
            EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
        }
        for (const Vec3& p : sphere.positions) {
            EXPECT_NEAR(length(p - Vec3{1, 2, 3}), 2.0, 1e-12);
        }
    }
}

TEST(GeneratedMeshes, SoupIsReproducibleInsideTheUnitCubeAndShrinksWithCount) {
    const Scene a = test::make_triangle_soup(2000, 5);
    const Scene b = test::make_triangle_soup(2000, 5);
    ASSERT_EQ(a.polygons.size(), 2000u);
    expect_unit_outward_triangles(a);
    EXPECT_EQ(a.positions, b.positions);
    const Box3 box = a.bounds();
    for (int k = 0; k < 3; ++k) {
        EXPECT_GE(box.lo[k], 0.0);
        EXPECT_LE(box.hi[k], 1.0);
    }
    const auto mean_edge = [](const Scene& s) {
        double sum = 0.0;
        for (const Polygon& p : s.polygons) {
            sum += length(s.corner_position(p, 1) - s.corner_position(p, 0));
        }
        return sum / static_cast<double>(s.polygons.size());
    };
    EXPECT_LT(mean_edge(test::make_triangle_soup(20000, 5)), 0.6 * mean_edge(a));
}

TEST(GeneratedMeshes, CubeSphereHasTwelveSquaresOfTrianglesOnTheUnitSphere) {
    for (const std::uint32_t asked : {12u, 1000u, 20000u}) {
        const Scene sphere = test::make_cube_sphere(asked);
        expect_unit_outward_triangles(sphere);
        const auto n = static_cast<std::uint32_t>(std::sqrt(asked / 12.0));
        EXPECT_EQ(sphere.polygons.size(), 12u * n * n);  // 6 faces, n x n squares, 2 triangles
        for (const Polygon& p : sphere.polygons) {
            const Vec3 centroid = sphere.corner_position(p, 0) + sphere.corner_position(p, 1) +
                                  sphere.corner_position(p, 2);
            EXPECT_GT(dot(p.normal, centroid), 0.0);
        }
        for (const Vec3& p : sphere.positions) {
            EXPECT_NEAR(length(p), 1.0, 1e-12);
        }
    }
}

}  // namespace
}  // namespace rt
