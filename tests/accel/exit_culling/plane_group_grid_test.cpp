// A plane group's grid (plane_group_grid.h) must name every polygon of the group the exact test
// reports hit, whenever it answers at all: rays through tile corners and shared edges, steep and
// shallow, from near and far, and it must say it is unsure near edge-on.
#include "rt/accel/exit_culling/plane_group_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "rt/accel/exit_culling/occupied_cells.h"
#include "rt/accel/hit_regions/polygon_reach.h"
#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt::test {
namespace {

constexpr int kTiles = 6;  // a side
constexpr int kHalfTiles = 3;

// A checkerboard of kTiles x kTiles unit tiles in the plane y = height, tilted about the z axis by
// `tilt` radians, and moved by `shift` along x and z: one plane group, whose normal is not along
// an axis when tilted.
Scene tiles(double height, double tilt, double shift = 0.0) {
    SceneBuilder b;
    const Vec3 along{std::cos(tilt), std::sin(tilt), 0.0};
    const Vec3 normal{-std::sin(tilt), std::cos(tilt), 0.0};
    const auto at = [&](double u, double w) { return along * u + Vec3{shift, height, w + shift}; };
    for (int i = 0; i < kTiles; ++i) {
        for (int k = 0; k < kTiles; ++k) {
            const auto u = static_cast<double>(i - kHalfTiles);
            const auto w = static_cast<double>(k - kHalfTiles);
            b.add_polygon({at(u, w), at(u + 1, w), at(u + 1, w + 1), at(u, w + 1)}, normal);
        }
    }
    return b.scene();
}

struct Group {
    PlaneGroupGrids grids;
    std::uint32_t grid = 0;
    double scale = 0.0;
};

Group group_of(const Scene& scene) {
    const CullingFrame frame = culling_frame(scene);
    std::vector<Box3> boxes;
    std::vector<std::uint32_t> members;
    Group g;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        boxes.push_back(polygon_reach(scene, id, 0.0, frame.rounding).box);
        members.push_back(id);
        const Vec3 c = scene.corner_position(scene.polygons[id], 0);
        g.scale = std::max({g.scale, std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
    }
    g.grid = g.grids.add(scene.polygons[0].normal, members, boxes);
    return g;
}

// Each tile the exact test reports hit must be among the grid's candidates, when it answers.
// Returns how many rays it answered.
int expect_candidates_hold_every_hit(const Scene& scene, const Group& g,
                                     const std::vector<Ray>& rays, std::uint32_t most_named = 4) {
    const Vec3 leader = scene.corner_position(scene.polygons[0], 0);
    int answered = 0;
    for (const Ray& ray : rays) {
        std::array<std::uint32_t, 16> out{};
        std::uint32_t count = 0;
        if (!g.grids.add_candidates(g.grid, ray, leader, g.scale, out, count)) {
            continue;
        }
        ++answered;
        EXPECT_LE(count, most_named) << "a point near the board is near four tiles at most";
        for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
            if (intersect_polygon(ray, scene.polygon_view(id), {0.0, 1e300})) {
                EXPECT_NE(std::find(out.begin(), out.begin() + count, id), out.begin() + count)
                    << "tile " << id << " is hit but not named";
            }
        }
    }
    return answered;
}

// Rays aimed at the tiles' corners and edges (where neighbours meet), and at random points.
std::vector<Ray> aimed_rays(const Scene& scene, std::uint64_t seed, double min_steepness) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Ray> rays;
    for (int n = 0; n < 6000; ++n) {
        const Polygon& p = scene.polygons[static_cast<std::size_t>(n) % scene.polygons.size()];
        const Vec3 a = scene.corner_position(p, 0);
        const Vec3 b = scene.corner_position(p, 1);
        const Vec3 c = scene.corner_position(p, 2);
        Vec3 target = a;  // a corner
        if (n % 3 == 1) {
            target = a + (b - a) * std::fabs(unit(rng));  // an edge
        } else if (n % 3 == 2) {
            target = a + (b - a) * std::fabs(unit(rng)) + (c - b) * std::fabs(unit(rng));
        }
        Vec3 d{unit(rng), unit(rng), unit(rng)};
        const Vec3& normal = p.normal;
        if (std::fabs(dot(normalize(d), normal)) < min_steepness) {
            d = d + normal * (min_steepness * 2.0);
        }
        const double distance = n % 2 == 0 ? 0.01 : 40.0;
        rays.push_back({target - normalize(d) * distance, d});
    }
    return rays;
}

TEST(PlaneGroupGrid, NamesEveryTileTheExactTestHits) {
    for (const double tilt : {0.0, 0.3}) {
        for (const double height : {0.0, 1e4}) {
            const Scene scene = tiles(height, tilt);
            const Group g = group_of(scene);
            const std::vector<Ray> rays = aimed_rays(scene, 61, 0.01);
            EXPECT_GT(expect_candidates_hold_every_hit(scene, g, rays),
                      static_cast<int>(rays.size()) * 9 / 10)
                << "tilt " << tilt << " height " << height;
        }
    }
}

// Far from the origin, the crossing's cell index rounds by more than a millionth of a cell: the
// grid keeps half its margin for it. Farther still, the group's spread makes the tolerance too
// wide, and the grid says it is unsure rather than name a wrong tile.
TEST(PlaneGroupGrid, NamesEveryTileFarFromTheOrigin) {
    for (const double shift : {1e6, 1e7, 1e9}) {
        const Scene scene = tiles(0.0, 0.1, shift);
        const Group g = group_of(scene);
        const std::vector<Ray> rays = aimed_rays(scene, 63, 0.01);
        // The tolerance grows with the distance, and so does the number of tiles named.
        const int answered = expect_candidates_hold_every_hit(scene, g, rays, 16);
        if (shift < 1e8) {
            EXPECT_GT(answered, 0) << shift;
        }
    }
}

TEST(PlaneGroupGrid, NamesEveryTileOnShallowRays) {
    const Scene scene = tiles(0.0, 0.2);
    const Group g = group_of(scene);
    const std::vector<Ray> rays = aimed_rays(scene, 62, 1e-5);
    EXPECT_GT(expect_candidates_hold_every_hit(scene, g, rays), 0);
}

TEST(PlaneGroupGrid, NamesOneTileInsideIt) {
    const Scene scene = tiles(0.0, 0.0);
    const Group g = group_of(scene);
    const Vec3 leader = scene.corner_position(scene.polygons[0], 0);
    std::array<std::uint32_t, 16> out{};
    std::uint32_t count = 0;
    // Straight down onto the middle of tile (i, k) = (1, 2): x in [-2, -1], z in [-1, 0].
    const Ray down{{-1.5, 3.0, -0.5}, {0.1, -1.0, 0.05}};
    ASSERT_TRUE(g.grids.add_candidates(g.grid, down, leader, g.scale, out, count));
    ASSERT_EQ(count, 1u);
    EXPECT_EQ(out[0], static_cast<std::uint32_t>(1 * kTiles + 2));
    // Off the board: no tile.
    count = 0;
    const Ray beside{{50.0, 3.0, 0.5}, {0.0, -1.0, 0.0}};
    ASSERT_TRUE(g.grids.add_candidates(g.grid, beside, leader, g.scale, out, count));
    EXPECT_EQ(count, 0u);
}

TEST(PlaneGroupGrid, UnsureNearEdgeOnOrWhenFull) {
    const Scene scene = tiles(0.0, 0.0);
    const Group g = group_of(scene);
    const Vec3 leader = scene.corner_position(scene.polygons[0], 0);
    std::array<std::uint32_t, 16> out{};
    std::uint32_t count = 0;
    const Ray skimming{{-1.5, 1e-3, -0.5}, {1.0, -1e-7, 0.0}};
    EXPECT_FALSE(g.grids.add_candidates(g.grid, skimming, leader, g.scale, out, count));
    // Onto a corner shared by four tiles, with room for three.
    count = 0;
    const Ray onto_corner{{0.0, 2.0, 0.0}, {0.0, -1.0, 0.0}};
    EXPECT_FALSE(g.grids.add_candidates(g.grid, onto_corner, leader, g.scale,
                                        std::span<std::uint32_t>(out.data(), 3), count));
}

}  // namespace
}  // namespace rt::test
