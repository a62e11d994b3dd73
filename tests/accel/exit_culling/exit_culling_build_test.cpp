// The table's build may run on several threads and skips work that cannot change it (full cells
// in the grazing pass); neither may change a single bit of it.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "rt/accel/exit_culling/exit_culling_table.h"
#include "rt/accel/exit_culling/occupied_cells.h"
#include "rt/accel/hit_regions/polygon_reach.h"
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

using BoxBits = std::array<double, 6>;

BoxBits bits_of(const Box3& box) {
    return {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
}

// The boxes of the occupied cells found by asking every cell of the grid about every reach,
// sorted.
std::vector<BoxBits> every_cell_asked(const ReachSource& reaches, const OccupiedCells& cells) {
    const int resolution = cells.resolution();
    std::vector<Box3> every(static_cast<std::size_t>(resolution) * resolution * resolution);
    for (std::size_t id = 0; id < reaches.count(); ++id) {
        const PolygonReach reach = reaches(id);
        for (std::size_t cell = 0; !reach.box.empty() && cell < every.size(); ++cell) {
            const Box3 piece = intersection(reach.box, cells.cell_box(static_cast<int>(cell)));
            if (!piece.empty() && slab_meets_box(reach, piece)) {
                every[cell].add(piece);
            }
        }
    }
    std::vector<BoxBits> boxes;
    for (const Box3& box : every) {
        if (!box.empty()) {
            boxes.push_back(bits_of(box));
        }
    }
    std::sort(boxes.begin(), boxes.end());
    return boxes;
}

// The occupied cells' boxes as the cells keep them (the leaves of their tree), sorted.
std::vector<BoxBits> occupied_boxes(const OccupiedCells& cells) {
    std::vector<BoxBits> boxes;
    for (const OccupiedCells::Node& node : cells.tree()) {
        if (node.first_child < 0) {
            boxes.push_back(bits_of(node.box));
        }
    }
    std::sort(boxes.begin(), boxes.end());
    return boxes;
}

// Each reach grows only the cells its box meets, found from its corners' cells and the exact
// boundaries (OccupiedCells::cell_range): the occupied cells' boxes must be those found by asking
// every cell of the grid about every reach.
TEST(ExitCullingBuild, OccupiedCellsAreThoseOfEveryCellAsked) {
    const Scene scenes[] = {make_soup(24, 800), make_sphere({1, 2, 3}, 5.0, 16, 32, false),
                            make_boxes(14, 10), load_twocubes()};
    for (const Scene& scene : scenes) {
        const CullingFrame frame = culling_frame(scene);
        const ReachSource reaches{&scene, frame.rounding};
        for (const int resolution : {1, 5, 8, 13}) {
            const OccupiedCells cells(frame, reaches, resolution, 1);
            const std::vector<BoxBits> expected = every_cell_asked(reaches, cells);
            EXPECT_EQ(occupied_boxes(cells), expected)
                << scene.polygons.size() << " polygons, " << resolution << "^3 cells";
            EXPECT_FALSE(expected.empty());
        }
    }
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
