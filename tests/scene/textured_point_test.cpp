// Where a point lies on a texture-mapped cell (-V) in grid coordinates, and how a normal map's
// pixel turns the normal: against points placed by the bilinear map itself and normals worked out
// by hand.
#include "rt/scene/textured_point.h"

#include <cmath>

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

void expect_near(const Vec3& got, const Vec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

// Cell (row 2, column 5) of a grid, a trapezoid in the plane z = 1 (not a parallelogram, so that
// the bilinear map is not linear): corners (r, c) (r, c+1) (r+1, c+1) (r+1, c).
struct Trapezoid {
    Trapezoid() {
        builder.add_polygon({a, b, c, d}, {0, 0, 1});
        Scene& scene = builder.scene();
        TextureCell cell;
        cell.tangent_u = {1, 0, 0};
        cell.tangent_v = {0, 1, 0};
        cell.row = 2;
        cell.column = 5;
        scene.texture_cells = {cell};
        scene.texture_grids = {TextureGrid{4, 8}};
        scene.polygons[0].texture_cell = 0;
    }
    Vec3 at(double s, double t) const {
        return a * ((1 - s) * (1 - t)) + b * (s * (1 - t)) + c * (s * t) + d * ((1 - s) * t);
    }
    Vec3 a{0, 0, 1};
    Vec3 b{2, 0.2, 1};
    Vec3 c{1.6, 1.5, 1};
    Vec3 d{0.1, 1, 1};
    test::SceneBuilder builder;
};

TEST(TexturedPoint, GridCoordinatesInvertTheCellsBilinearMap) {
    Trapezoid cell;
    for (const double s : {0.0, 0.1, 0.5, 0.93, 1.0}) {
        for (const double t : {0.0, 0.3, 0.5, 0.77, 1.0}) {
            const GridCoordinates g = grid_coordinates(cell.builder.scene(), 0, cell.at(s, t));
            EXPECT_NEAR(g.u, 5 + s, 1e-9) << s << " " << t;
            EXPECT_NEAR(g.v, 2 + t, 1e-9) << s << " " << t;
        }
    }
}

TEST(TexturedPoint, ANormalMapPixelTurnsTheNormalInTheCellsFrame) {
    const Vec3 n{0, 0, 1};
    const Vec3 u{1, 0, 0};
    const Vec3 v{0, 1, 0};
    // Red along u, green toward decreasing v (up the picture), blue along the normal.
    expect_near(normal_map_normal({1, 0.5, 1}, n, u, v), normalize(Vec3{1, 0, 1}));
    expect_near(normal_map_normal({0.5, 1, 1}, n, u, v), normalize(Vec3{0, -1, 1}));
    expect_near(normal_map_normal({0.5, 0.5, 1}, n, u, v), n);
    // A pixel pointing along or into the surface leaves the normal alone.
    expect_near(normal_map_normal({1, 0.5, 0.5}, n, u, v), n);
    expect_near(normal_map_normal({0.5, 0.5, 0}, n, u, v), n);
    // Around a bent normal, the frame is turned with it: u made perpendicular to it.
    const Vec3 bent = normalize(Vec3{1, 0, 1});
    expect_near(normal_map_normal({1, 0.5, 1}, bent, u, v), Vec3{1, 0, 0});
}

TEST(TexturedPoint, AColourMapTintsByWhereThePointIsOnTheGrid) {
    // A 4 x 8 grid under an 8 x 4 picture: each cell one pixel wide and one tall; the cell
    // (2, 5) under pixel (5, 2), its neighbour to the right under pixel (6, 2).
    Trapezoid cell;
    Scene& scene = cell.builder.scene();
    TextureImage picture{8, 4, std::vector<std::uint8_t>(8 * 4 * 3, 0), ""};
    const auto set = [&](int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        const std::size_t at = 3 * static_cast<std::size_t>(y * 8 + x);
        picture.rgb[at] = r;
        picture.rgb[at + 1] = g;
        picture.rgb[at + 2] = b;
    };
    set(5, 2, 255, 51, 102);
    set(6, 2, 255, 51, 102);
    set(5, 1, 255, 51, 102);
    set(6, 1, 255, 51, 102);
    scene.texture_images = {picture};
    scene.texture_grids[0].colour_map = 0;
    scene.texture_cells[0].color = {0.5, 1, 1};
    scene.attributes[0].color = {1, 0.5, 1};
    // At the cell's right edge, halfway up: between pixel centres (5, 2) and (6, 2), both lit.
    const Vec3 point = cell.at(1.0, 0.5);
    const TexturedPoint t = textured_point(scene, 0, point);
    EXPECT_NEAR(t.color.r, 0.5, 1e-12);
    EXPECT_NEAR(t.color.g, 0.2, 1e-12);
    EXPECT_NEAR(t.color.b, 0.4, 1e-12);
    const Rgb c = surface_color(scene, 0, point);
    EXPECT_NEAR(c.g, 0.1, 1e-12);
    // At the cell's bottom left, a quarter of the way between lit and dark pixels each way.
    EXPECT_NEAR(textured_point(scene, 0, cell.at(0.0, 1.0)).color.g, 0.2 * 0.5 * 0.5, 1e-12);
}

}  // namespace
}  // namespace rt
