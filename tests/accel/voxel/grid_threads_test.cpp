// One const voxel accelerator serves every rendering thread: answers from many threads at once are
// the single-threaded ones.
#include <thread>

#include "rt/accel/make_accelerator.h"

#include <gtest/gtest.h>

#include "accel/grid_test_support.h"

namespace rt::test {
namespace {

TEST(VoxelMethodsAcrossThreads, GiveTheSingleThreadedAnswers) {
    const Scene scene = random_triangle_soup(400, 61);
    const std::vector<RayCase> rays = random_rays({{0, 0, 0}, {1, 1, 1}}, 8000, 62);
    AccelSettings seads;
    seads.kind = AccelKind::Seads;
    seads.seads_resolution = 10;
    AccelSettings octree;
    octree.kind = AccelKind::Octree;
    octree.octree.depth = 6;
    for (const AccelSettings& settings : {seads, octree}) {
        const auto accel = make_accelerator(scene, settings);
        std::vector<std::optional<Hit>> alone(rays.size());
        TraceCounters counters;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            alone[i] = accel->closest_hit(rays[i].ray, rays[i].t, counters);
        }
        constexpr int kThreads = 4;
        std::vector<std::vector<std::optional<Hit>>> together(
            kThreads, std::vector<std::optional<Hit>>(rays.size()));
        std::vector<std::thread> threads;
        for (int k = 0; k < kThreads; ++k) {
            threads.emplace_back([&, k] {
                TraceCounters own;
                // Half the threads go through the rays backwards.
                for (std::size_t n = 0; n < rays.size(); ++n) {
                    const std::size_t i = k % 2 == 0 ? n : rays.size() - 1 - n;
                    together[k][i] = accel->closest_hit(rays[i].ray, rays[i].t, own);
                }
            });
        }
        for (std::thread& t : threads) {
            t.join();
        }
        for (int k = 0; k < kThreads; ++k) {
            for (std::size_t i = 0; i < rays.size(); ++i) {
                ASSERT_EQ(together[k][i].has_value(), alone[i].has_value()) << i;
                if (alone[i]) {
                    EXPECT_EQ(together[k][i]->t, alone[i]->t);
                    EXPECT_EQ(together[k][i]->polygon, alone[i]->polygon);
                }
            }
        }
    }
}

}  // namespace
}  // namespace rt::test
