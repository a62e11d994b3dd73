// What render() reports besides the picture: the threads it used and the rays it traced.
#include <cmath>

#include "rt/accel/brute_force.h"
#include "rt/render/renderer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

RenderStatistics render_box(int threads, const PixelRect& window, double emission = -1,
                            Film* picture = nullptr) {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, false);
    if (emission >= 0) {
        for (Attribute& a : scene.attributes) {
            a.color = {1, 1, 1};
            a.emission = emission;
        }
    }
    scene.view.look = {0, 0, 0};
    const BruteForce accel(scene);
    RenderSettings settings;
    settings.window = window;
    settings.threads = threads;
    RenderObserver observer;
    RenderStatistics statistics;
    Film film = render(scene, accel, settings, observer, statistics);
    if (picture != nullptr) {
        *picture = std::move(film);
    }
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

// A film holds floats: an intensity beyond their range (here an emitter of 1e39, which no
// Attributes file may give) is counted and taken as black, and never reaches the film.
TEST(RenderStatistics, IntensitiesBeyondTheFloatRangeAreCountedAsBlack) {
    EXPECT_EQ(render_box(1, {0, 0, 7, 7}, 1.0).unrepresentable_samples, 0u);
    Film film(1, 1, {0, 0, 0, 0});
    const RenderStatistics statistics = render_box(2, {0, 0, 7, 7}, 1e39, &film);
    EXPECT_GT(statistics.unrepresentable_samples, 0u);
    int black = 0;
    for (const float v : film.data()) {
        ASSERT_TRUE(std::isfinite(v));
        black += v == 0.0f;
    }
    EXPECT_GE(black, 3);  // at least the pixel of one such sample
}

}  // namespace
}  // namespace rt
