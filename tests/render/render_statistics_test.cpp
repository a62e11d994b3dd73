// What render() reports besides the picture: the threads it used and the rays it traced.
#include "rt/accel/brute_force.h"
#include "rt/render/renderer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

RenderStatistics render_box(int threads, const PixelRect& window) {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, false);
    scene.view.look = {0, 0, 0};
    const BruteForce accel(scene);
    RenderSettings settings;
    settings.window = window;
    settings.threads = threads;
    RenderObserver observer;
    RenderStatistics statistics;
    render(scene, accel, settings, observer, statistics);
    return statistics;
}

TEST(RenderStatistics, ThreadsAsAskedButNeverMoreThanRows) {
    EXPECT_EQ(render_box(3, {0, 0, 15, 15}).threads, 3);
    EXPECT_EQ(render_box(5, {0, 0, 15, 1}).threads, 2);
    EXPECT_GE(render_box(0, {0, 0, 15, 15}).threads, 1);  // one per core
}

TEST(RenderStatistics, CountsAtLeastOneRayPerPixel) {
    const RenderStatistics statistics = render_box(2, {0, 0, 15, 15});
    EXPECT_GE(statistics.counters.rays, 16u * 16u);
    EXPECT_GT(statistics.counters.hits, 0u);
    EXPECT_EQ(statistics.rows_done, 16);
}

}  // namespace
}  // namespace rt
