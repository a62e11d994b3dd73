// SEADS against brute force: identical answers on random and adversarial rays, grids of 1 to 256
// voxels a side, and the refusal of absurd grids.
#include "rt/accel/seads/seads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/core/error.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "accel/grid_test_support.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

AccelSettings seads(int side) {
    AccelSettings s;
    s.kind = AccelKind::Seads;
    s.seads_resolution = side;
    return s;
}

TEST(Seads, RandomSoupMatchesBruteForceAtEveryResolution) {
    const Scene scene = random_triangle_soup(300, 1);
    for (const int side : {1, 2, 7, 32}) {
        const Seads accel(scene, seads(side));
        expect_same_as_brute_force(scene, accel, random_rays(accel.grid().world, 12000, side));
    }
}

TEST(Seads, ClosedMeshesMatchBruteForce) {
    const Scene sphere = make_sphere({0.1, 0.2, 0.3}, 2.0, 16, 24, true);
    const Seads on_sphere(sphere, seads(12));
    expect_same_as_brute_force(sphere, on_sphere, random_rays(on_sphere.grid().world, 15000, 5));

    const Scene box = make_box({-1, -2, -3}, {1, 2, 3}, false);
    const Seads on_box(box, seads(5));
    expect_same_as_brute_force(box, on_box, random_rays(on_box.grid().world, 15000, 6));
}

TEST(Seads, TwoCubesSceneMatchesBruteForce) {
    Diagnostics diagnostics;
    const Scene scene =
        load_scene(source_dir() / "scenes/twocubes.scn", ReaderDialect{}, diagnostics);
    const Seads accel(scene, seads(8));
    expect_same_as_brute_force(scene, accel, random_rays(accel.grid().world, 15000, 7));
}

TEST(Seads, FinestGridOf256ASideMatchesBruteForce) {
    const Scene scene = random_triangle_soup(60, 3);
    const Seads accel(scene, seads(256));
    expect_same_as_brute_force(scene, accel, random_rays(accel.grid().world, 4000, 8));
    EXPECT_GE(accel.memory_bytes(), 256u * 256u * 256u * sizeof(std::uint32_t));
}

TEST(Seads, MostlyEmptyGridMatchesBruteForce) {
    SceneBuilder b;
    b.add_polygon({{0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0}});
    b.add_polygon({{1, 1, 1}, {0.99, 1, 1}, {1, 0.99, 1}});
    b.add_polygon({{0.5, 0.5, 0.5}, {0.6, 0.5, 0.5}, {0.5, 0.6, 0.5}});
    const Seads accel(b.scene(), seads(64));
    // Random rays almost never meet the three specks; half are turned towards one of them, to
    // somewhere within the speck's size of its middle.
    std::vector<RayCase> rays = random_rays(accel.grid().world, 5000, 9);
    const Vec3 middles[] = {{0.003, 0.003, 0}, {0.997, 0.997, 1}, {0.53, 0.53, 0.5}};
    const double sizes[] = {0.01, 0.01, 0.1};
    for (std::size_t i = 0; i < rays.size(); i += 2) {
        const Vec3 wobble{std::sin(1.0 * i), std::cos(1.3 * i), std::sin(1.7 * i)};
        const Vec3 target = middles[i % 3] + wobble * (0.3 * sizes[i % 3]);
        rays[i].ray.direction = target - rays[i].ray.origin;
        rays[i].t = Interval{};
    }
    expect_same_as_brute_force(b.scene(), accel, rays);
}

// The clearance the walk leaps by is the chessboard distance to the nearest voxel with polygons,
// checked here against the definition, voxel by voxel.
TEST(Seads, ClearanceIsTheChessboardDistanceToTheNearestOccupiedVoxel) {
    const Scene scene = random_triangle_soup(12, 4);
    const Seads accel(scene, seads(14));
    const SeadsGrid& grid = accel.grid();
    std::vector<std::array<int, 3>> occupied;
    for (int z = 0; z < grid.side; ++z) {
        for (int y = 0; y < grid.side; ++y) {
            for (int x = 0; x < grid.side; ++x) {
                if (!grid.voxel(grid.index(x, y, z)).empty()) {
                    occupied.push_back({x, y, z});
                }
            }
        }
    }
    ASSERT_FALSE(occupied.empty());
    int leaps = 0;
    for (int z = 0; z < grid.side; ++z) {
        for (int y = 0; y < grid.side; ++y) {
            for (int x = 0; x < grid.side; ++x) {
                int nearest = 255;
                for (const auto& o : occupied) {
                    nearest = std::min(nearest, std::max({std::abs(o[0] - x), std::abs(o[1] - y),
                                                          std::abs(o[2] - z)}));
                }
                EXPECT_EQ(grid.clearance[grid.index(x, y, z)], nearest)
                    << x << " " << y << " " << z;
                leaps += nearest >= 2 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(leaps, 0);  // the scene leaves room to leap
}

// Leaping over empty space and visiting each voxel (as -tv needs) give the same answers, and
// leaping visits fewer voxels.
TEST(Seads, LeapingOverEmptySpaceMatchesBruteForceWithFewerVisits) {
    const Scene scene = random_triangle_soup(40, 9);
    const Seads leaping(scene, seads(40));
    AccelSettings counting = seads(40);
    counting.terminate_after_voxels = 1u << 30;
    const Seads visiting(scene, counting);
    const std::vector<RayCase> rays = random_rays(leaping.grid().world, 20000, 10);
    const TraceCounters leaps = expect_same_as_brute_force(scene, leaping, rays);
    const TraceCounters visits = expect_same_as_brute_force(scene, visiting, rays);
    EXPECT_LT(leaps.voxels_stepped * 2, visits.voxels_stepped);
}

TEST(Seads, RefusesAbsurdGridsBeforeAllocating) {
    const Scene scene = make_box({0, 0, 0}, {1, 1, 1}, true);
    EXPECT_THROW(Seads(scene, seads(0)), UsageError);
    EXPECT_THROW(Seads(scene, seads(400)), UsageError);
    EXPECT_THROW(Seads(scene, seads(2000000000)), UsageError);
    try {
        Seads(scene, seads(1000));
        ADD_FAILURE() << "no error for 1000 voxels a side";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("1000 voxels a side"), std::string::npos) << e.what();
    }
}

TEST(Seads, EveryPolygonIsFiledInEveryVoxelItTouches) {
    const Scene scene = random_triangle_soup(200, 11);
    const Seads accel(scene, seads(6));
    const SeadsGrid& grid = accel.grid();
    for (int z = 0; z < grid.side; ++z) {
        for (int y = 0; y < grid.side; ++y) {
            for (int x = 0; x < grid.side; ++x) {
                const auto ids = grid.voxel(grid.index(x, y, z));
                EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
            }
        }
    }
    // A triangle's centroid lies in it, so its voxel must list it.
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        const Vec3 c = (scene.corner_position(p, 0) + scene.corner_position(p, 1) +
                        scene.corner_position(p, 2)) /
                       3.0;
        int cell[3];
        for (int a = 0; a < 3; ++a) {
            cell[a] = static_cast<int>((c[a] - grid.world.lo[a]) / grid.voxel_size[a]);
        }
        const auto ids = grid.voxel(grid.index(cell[0], cell[1], cell[2]));
        EXPECT_TRUE(std::binary_search(ids.begin(), ids.end(), id)) << id;
    }
}

TEST(Seads, CountsVoxelsAndTestsFewerPolygonsThanBruteForce) {
    const Scene scene = random_triangle_soup(400, 12);
    const Seads accel(scene, seads(16));
    const std::vector<RayCase> rays = random_rays(accel.grid().world, 2000, 13);
    const TraceCounters counters = expect_same_as_brute_force(scene, accel, rays);
    EXPECT_GT(counters.voxels_stepped, rays.size());
    EXPECT_LT(counters.polygon_tests, 400u * rays.size() / 4);
}

}  // namespace
}  // namespace rt::test

namespace rt::test {
namespace {

// SEADS's own boundary arithmetic: plane k of an axis at world.lo + k * voxel size.
Lattice seads_lattice(const SeadsGrid& grid) {
    return [grid_lo = grid.world.lo, size = grid.voxel_size](int axis, int k) {
        return grid_lo[axis] + k * size[axis];
    };
}

TEST(Seads, PolygonsInVoxelFacesAndRaysAlongThemMatchBruteForce) {
    for (const int side : {4, 9}) {
        Scene scene = unit_cube_anchors();
        const SeadsGrid bare = build_seads_grid(scene, side, false);
        add_lattice_faces(scene, seads_lattice(bare), side, 150, side);
        const Seads accel(scene, seads(side));
        ASSERT_EQ(accel.grid().world.lo, bare.world.lo);
        expect_same_as_brute_force(scene, accel, lattice_rays(seads_lattice(bare), side, 12000, 3));
        expect_same_as_brute_force(scene, accel, random_rays(accel.grid().world, 4000, 4));
    }
}

}  // namespace
}  // namespace rt::test
