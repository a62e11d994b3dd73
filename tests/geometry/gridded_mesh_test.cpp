// Watertightness where many polygons meet in one plane: a closed box whose faces are grids of
// quads (or of triangles), so that four coplanar polygons share a corner and two share an edge in
// the middle of a flat face; and an octahedron, four triangles around each corner. Every
// coordinate and direction is dyadic, so the lines pass exactly through the shared corners and
// edges.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "support/line_hits.h"
#include "support/scene_builder.h"

namespace rt::test {
namespace {

// Adds the loop turned so that it runs counter-clockwise seen from `outward`.
void add_outward(SceneBuilder& builder, std::vector<Vec3> loop, const Vec3& outward) {
    if (dot(newell_normal(loop), outward) < 0.0) {
        std::reverse(loop.begin(), loop.end());
    }
    builder.add_polygon(loop, outward);
}

// One face of the cube [-cells/2, cells/2]^3, on the side `side` of axis `axis`, as a grid of
// cells x cells unit cells.
void add_face_grid(SceneBuilder& builder, int axis, double side, int cells, bool triangles) {
    const double half = cells / 2.0;
    Vec3 outward;
    outward[axis] = side;
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    const auto at = [&](int du, int dv) {
        Vec3 p;
        p[axis] = side;
        p[u] = -half + du;
        p[v] = -half + dv;
        return p;
    };
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            if (triangles) {
                add_outward(builder, {at(i, j), at(i + 1, j), at(i + 1, j + 1)}, outward);
                add_outward(builder, {at(i, j), at(i + 1, j + 1), at(i, j + 1)}, outward);
            } else {
                add_outward(builder, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)},
                            outward);
            }
        }
    }
}

// The closed cube [-1, 1]^3, each face a 2 x 2 grid of unit cells (a corner shared by four
// coplanar cells in the middle of each face), as quads or split into triangles along a diagonal.
Scene gridded_cube(bool triangles) {
    SceneBuilder builder;
    for (int axis = 0; axis < 3; ++axis) {
        for (const double side : {-1.0, 1.0}) {
            add_face_grid(builder, axis, side, 2, triangles);
        }
    }
    return std::move(builder.scene());
}

Scene octahedron() {
    SceneBuilder builder;
    for (const double x : {-1.0, 1.0}) {
        for (const double y : {-1.0, 1.0}) {
            for (const double z : {-1.0, 1.0}) {
                add_outward(builder, {{x, 0, 0}, {0, y, 0}, {0, 0, z}}, {x, y, z});
            }
        }
    }
    return std::move(builder.scene());
}

// Every corner and every edge middle of the scene's polygons, each once.
std::vector<Vec3> corners_and_edge_middles(const Scene& scene) {
    std::vector<Vec3> points;
    for (const Polygon& p : scene.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 a = scene.corner_position(p, k);
            const Vec3 b = scene.corner_position(p, (k + 1) % p.corner_count);
            points.push_back(a);
            points.push_back((a + b) * 0.5);
        }
    }
    const auto key = [](const Vec3& p) { return std::tuple(p.x, p.y, p.z); };
    std::sort(points.begin(), points.end(),
              [&](const Vec3& a, const Vec3& b) { return key(a) < key(b); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

class GriddedCube : public ::testing::TestWithParam<bool> {
protected:
    Scene cube_ = gridded_cube(GetParam());
};

TEST_P(GriddedCube, LoopsAreConsistent) {
    expect_consistent_loops(cube_);
}

TEST_P(GriddedCube, LinesExactlyThroughSharedCornersAndEdges) {
    for (const Vec3& point : corners_and_edge_middles(cube_)) {
        // Toward the centre: through the inside.
        expect_two_crossings(cube_, ray_through(point, point * -0.25));
        for (const Vec3& direction : dyadic_directions()) {
            expect_even_crossing(cube_, ray_through(point, direction));
        }
        if (HasFatalFailure()) {
            return;  // one report, not thousands
        }
    }
}

TEST_P(GriddedCube, AxisParallelLinesAlongTheGrid) {
    // On the grid lines, between them, and outside, in half steps.
    for (int i = -3; i <= 3; ++i) {
        for (int j = -3; j <= 3; ++j) {
            const double a = 0.5 * i;
            const double b = 0.5 * j;
            const bool strictly_inside = std::abs(i) < 2 && std::abs(j) < 2;
            for (const Ray& ray : {Ray{{a, b, -8}, {0, 0, 1}}, Ray{{-8, a, b}, {1, 0, 0}},
                                   Ray{{a, -8, b}, {0, 1, 0}}, Ray{{a, b, 8}, {0, 0, -1}}}) {
                expect_even_crossing(cube_, ray);
                if (strictly_inside) {
                    expect_two_crossings(cube_, ray);
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(QuadsAndTriangles, GriddedCube, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& param) {
                             return param.param ? "Triangles" : "Quads";
                         });

TEST(Octahedron, LinesExactlyThroughCornersAndEdges) {
    const Scene solid = octahedron();
    expect_consistent_loops(solid);
    for (const Vec3& point : corners_and_edge_middles(solid)) {
        // Through the centre: inside.
        expect_two_crossings(solid, ray_through(point, point * -0.5));
        for (const Vec3& direction : dyadic_directions()) {
            expect_even_crossing(solid, ray_through(point, direction));
        }
    }
}

}  // namespace
}  // namespace rt::test
