// The table's build may run on several threads and skips work that cannot change it (full cells
// in the grazing pass); neither may change a single bit of it.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "rt/accel/exit_culling/exit_culling_table.h"
#include "rt/accel/parallel_parts.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

namespace rt::test {
namespace {

std::vector<std::uint16_t> rows_of(const ExitCullingTable& table) {
    return {table.bin_rows().begin(), table.bin_rows().end()};
}

TEST(ExitCullingBuild, AnyThreadCountBuildsTheSameTable) {
    const Scene scenes[] = {make_soup(21, 3000), make_soup(22, 500, true),
                            make_sphere({1, 2, 3}, 5.0, 20, 40, false), load_twocubes()};
    double emptiest = 0.0;
    for (const Scene& scene : scenes) {
        for (const int resolution : {3, 8, 12}) {
            const ExitCullingTable one(scene, resolution, 8, 1);
            emptiest = std::max(emptiest, one.empty_fraction());
            for (const int threads : {2, 3, 7}) {
                const ExitCullingTable many(scene, resolution, 8, threads);
                EXPECT_EQ(rows_of(one), rows_of(many))
                    << scene.polygons.size() << " polygons, " << resolution << "^3 cells, "
                    << threads << " threads";
            }
        }
    }
    EXPECT_GT(emptiest, 0.3) << "tables this full would prove little";
}

// The pass that answers most rays (every ray leaving a surface) rests on this: a cell a polygon
// crosses has every direction bin set. Points on polygons, at corners, edge midpoints and
// centroids, must all be found in full cells.
TEST(ExitCullingBuild, PointsOnPolygonsStartInFullCells) {
    const Scene scenes[] = {load_twocubes(), make_sphere({1, 2, 3}, 5.0, 12, 24, false),
                            make_soup(23, 300), make_boxes(13, 12)};
    for (const Scene& scene : scenes) {
        for (const int resolution : {4, 8, 13}) {
            const ExitCullingTable table(scene, resolution, 8);
            int points = 0;
            for (const Polygon& polygon : scene.polygons) {
                Vec3 centroid;
                for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
                    const Vec3 corner = scene.corner_position(polygon, k);
                    const Vec3 next =
                        scene.corner_position(polygon, (k + 1) % polygon.corner_count);
                    centroid += corner / static_cast<double>(polygon.corner_count);
                    for (const Vec3& p : {corner, 0.5 * (corner + next)}) {
                        EXPECT_TRUE(table.starts_in_full_cell(p))
                            << scene.polygons.size() << " polygons, " << resolution << "^3 cells";
                        ++points;
                    }
                }
                EXPECT_TRUE(table.starts_in_full_cell(centroid));
            }
            EXPECT_GT(points, 0);
        }
    }
}

TEST(ExitCullingBuild, PartsCoverTheRangeOnce) {
    for (const std::size_t count : {0u, 1u, 5u, 1000u}) {
        for (const int parts : {1, 2, 3, 8}) {
            std::vector<int> seen(count, 0);
            std::vector<int> part_of(count, -1);
            run_in_parts(count, parts, [&](std::size_t begin, std::size_t end, int part) {
                for (std::size_t i = begin; i < end; ++i) {
                    ++seen[i];
                    part_of[i] = part;
                }
            });
            for (std::size_t i = 0; i < count; ++i) {
                EXPECT_EQ(seen[i], 1) << count << " items in " << parts << " parts, item " << i;
                if (i > 0) {
                    EXPECT_GE(part_of[i], part_of[i - 1]) << "parts are contiguous, in order";
                }
            }
        }
    }
}

TEST(ExitCullingBuild, SharedOutItemsAreEachDoneOnce) {
    for (const std::size_t count : {0u, 1u, 5u, 1000u}) {
        for (const int threads : {0, 1, 2, 3, 8}) {
            // Each thread counts into its own slots: the items are shared out as they come.
            const int slots = std::max(threads, 1);
            std::vector<std::vector<int>> seen(static_cast<std::size_t>(slots),
                                               std::vector<int>(count, 0));
            bool thread_in_range = true;
            share_out(count, threads, [&](std::size_t i, int thread) {
                if (thread < 0 || thread >= slots) {
                    thread_in_range = false;
                    return;
                }
                ++seen[static_cast<std::size_t>(thread)][i];
            });
            EXPECT_TRUE(thread_in_range);
            for (std::size_t i = 0; i < count; ++i) {
                int total = 0;
                for (const std::vector<int>& own : seen) {
                    total += own[i];
                }
                EXPECT_EQ(total, 1) << count << " items on " << threads << " threads, item " << i;
            }
        }
    }
}

TEST(ExitCullingBuild, SmallScenesBuildOnTheCallingThread) {
    EXPECT_EQ(build_threads_for(0, 71), 1);
    EXPECT_GE(build_threads_for(0, 1000000), 1);
    EXPECT_EQ(build_threads_for(3, 71), 3);
}

}  // namespace
}  // namespace rt::test
