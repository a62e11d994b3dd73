// What render() tells its observer and how it stops: rows bottom up, every pixel announced once
// (-dc), and a stop request (Ctrl-C) keeping a contiguous run of finished rows from the bottom.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/render/renderer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr PixelRect kWindow{2, 3, 9, 12};  // 8 columns, 10 rows

// A lit box seen from the builder's eye, with an emissive lid so that pixels differ.
Scene lit_box() {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, false);
    scene.view.look = {0, 0, 0};
    scene.attributes[0].color = {0.8, 0.6, 0.4};
    scene.attributes[0].emission = 0.5;
    scene.attributes[0].diffuse = 0.5;
    return scene;
}

Film render_with(RenderObserver& observer, int threads, RenderStatistics& statistics,
                 const std::atomic<bool>* stop_now = nullptr, const Film* resume = nullptr) {
    const Scene scene = lit_box();
    const BruteForce accel(scene);
    RenderSettings settings;
    settings.window = kWindow;
    settings.threads = threads;
    settings.stop_now = stop_now;
    settings.resume = resume;
    return render(scene, accel, settings, observer, statistics);
}

// Remembers every call; asks to stop once `stop_after` rows are done (never if 0).
class RecordingObserver : public RenderObserver {
public:
    explicit RecordingObserver(int stop_after = 0, bool pixel_events = false)
        : stop_after_(stop_after), pixel_events_(pixel_events) {}
    void row_done(const RowDone& row) override {
        rows.push_back(row.y);
        samples += row.samples;
        EXPECT_EQ(row.rows_done, rows_before + static_cast<int>(rows.size()));
        EXPECT_EQ(row.rows_total, kWindow.height());
    }
    bool wants_pixel_events() const override { return pixel_events_; }
    void pixel_started(int x, int y) override { pixels.emplace_back(x, y); }
    bool should_stop() override {
        return stop_after_ > 0 && static_cast<int>(rows.size()) >= stop_after_;
    }

    int rows_before = 0;  ///< rows a resumed render starts with
    std::vector<int> rows;
    std::vector<std::pair<int, int>> pixels;
    std::uint64_t samples = 0;

private:
    int stop_after_;
    bool pixel_events_;
};

TEST(RendererObserver, OneThreadFinishesRowsFromTheBottomUp) {
    RecordingObserver observer;
    RenderStatistics statistics;
    const Film film = render_with(observer, 1, statistics);
    std::vector<int> expected;
    for (int y = kWindow.bottom; y >= kWindow.top; --y) {
        expected.push_back(y);
    }
    EXPECT_EQ(observer.rows, expected);
    EXPECT_TRUE(film.complete());
    EXPECT_FALSE(statistics.interrupted);
    EXPECT_TRUE(observer.pixels.empty());  // nobody asked for pixel events
}

// The samples each row reports (the progress bar's samples per second) are the eye rays traced.
TEST(RendererObserver, RowsReportTheEyeRaysTheyTook) {
    for (const int threads : {1, 3}) {
        RecordingObserver observer;
        RenderStatistics statistics;
        render_with(observer, threads, statistics);
        EXPECT_EQ(observer.samples, statistics.by_kind[RayKind::Eye].rays) << threads;
        EXPECT_GE(observer.samples, static_cast<std::uint64_t>(kWindow.width() * kWindow.height()));
    }
}

TEST(RendererObserver, EveryPixelIsAnnouncedOnceInDrawingOrder) {
    RecordingObserver observer(0, true);
    RenderStatistics statistics;
    render_with(observer, 1, statistics);
    std::vector<std::pair<int, int>> expected;
    for (int y = kWindow.bottom; y >= kWindow.top; --y) {
        for (int x = kWindow.left; x <= kWindow.right; ++x) {
            expected.emplace_back(x, y);
        }
    }
    EXPECT_EQ(observer.pixels, expected);
}

TEST(RendererObserver, AStopKeepsTheBottomRowsAsAFullRenderDrawsThem) {
    RecordingObserver full_observer;
    RenderStatistics full_statistics;
    const Film full = render_with(full_observer, 1, full_statistics);

    RecordingObserver observer(3);
    RenderStatistics statistics;
    const Film part = render_with(observer, 1, statistics);
    EXPECT_TRUE(statistics.interrupted);
    EXPECT_EQ(statistics.rows_done, 3);
    EXPECT_FALSE(part.complete());
    ASSERT_EQ(part.first_finished_row(), kWindow.bottom - 2);
    bool any_lit = false;
    for (int y = kWindow.top; y <= kWindow.bottom; ++y) {
        for (int x = kWindow.left; x <= kWindow.right; ++x) {
            if (y >= part.first_finished_row()) {
                EXPECT_EQ(part.pixel(x, y), full.pixel(x, y)) << x << " " << y;
                any_lit |= max_component(part.pixel(x, y)) > 0.0;
            } else {
                EXPECT_EQ(part.pixel(x, y), Rgb{}) << "never drawn: " << x << " " << y;
            }
        }
    }
    EXPECT_TRUE(any_lit);
}

TEST(RendererObserver, AStopWithSeveralThreadsKeepsAContiguousRun) {
    // Threads may have finished rows above a gap; only the run from the bottom counts.
    RecordingObserver observer(4);
    RenderStatistics statistics;
    const Film part = render_with(observer, 3, statistics);
    EXPECT_TRUE(statistics.interrupted);
    EXPECT_GE(statistics.rows_done, 4);
    EXPECT_LT(statistics.rows_done, kWindow.height());
    const int first = part.first_finished_row();
    EXPECT_LE(first, kWindow.bottom + 1);
    EXPECT_GT(first, kWindow.top);
    for (int y = first; y <= kWindow.bottom; ++y) {
        EXPECT_NE(std::find(observer.rows.begin(), observer.rows.end(), y), observer.rows.end())
            << "row " << y << " counted as finished but never reported";
    }
    if (first > kWindow.top) {
        // The row just above the run was not finished, or the run would include it.
        EXPECT_EQ(std::find(observer.rows.begin(), observer.rows.end(), first - 1),
                  observer.rows.end());
    }
}

// Sets the stop flag, as a signal handler does, when pixel `at` is about to be sampled.
class FlagAtPixel : public RecordingObserver {
public:
    FlagAtPixel(std::atomic<bool>& flag, std::pair<int, int> at)
        : RecordingObserver(0, true), flag_(flag), at_(at) {}
    void pixel_started(int x, int y) override {
        RecordingObserver::pixel_started(x, y);
        if (std::pair(x, y) == at_) {
            flag_ = true;
        }
    }

private:
    std::atomic<bool>& flag_;
    std::pair<int, int> at_;
};

// The flag is seen inside the row: the row being drawn is abandoned (black, though most of it was
// computed), no pixel after it is started, and the rows below are kept as a full render has them.
TEST(RendererStopFlag, AbandonsTheRowBeingDrawn) {
    RecordingObserver full_observer;
    RenderStatistics full_statistics;
    const Film full = render_with(full_observer, 1, full_statistics);
    int y = kWindow.bottom;  // the lowest row with a lit pixel
    const auto lit = [&](int row) {
        for (int x = kWindow.left; x <= kWindow.right; ++x) {
            if (max_component(full.pixel(x, row)) > 0.0) {
                return true;
            }
        }
        return false;
    };
    while (y > kWindow.top && !lit(y)) {
        --y;
    }
    ASSERT_TRUE(lit(y));

    std::atomic<bool> stop{false};
    FlagAtPixel observer(stop, {kWindow.right, y});  // the row's last pixel
    RenderStatistics statistics;
    const Film part = render_with(observer, 1, statistics, &stop);
    EXPECT_TRUE(statistics.interrupted);
    EXPECT_EQ(part.first_finished_row(), y + 1);
    EXPECT_EQ(observer.pixels.back(), std::pair(kWindow.right, y));
    for (int x = kWindow.left; x <= kWindow.right; ++x) {
        EXPECT_EQ(part.pixel(x, y), Rgb{}) << x;
        for (int below = y + 1; below <= kWindow.bottom; ++below) {
            EXPECT_EQ(part.pixel(x, below), full.pixel(x, below)) << x << " " << below;
        }
    }
}

TEST(RendererStopFlag, SetBeforeTheRenderFinishesNoRow) {
    std::atomic<bool> stop{true};
    RecordingObserver observer;
    RenderStatistics statistics;
    const Film part = render_with(observer, 2, statistics, &stop);
    EXPECT_TRUE(statistics.interrupted);
    EXPECT_EQ(part.first_finished_row(), kWindow.bottom + 1);
    EXPECT_TRUE(observer.rows.empty());
}

// A resumed render renders only the missing rows and completes the very picture, whatever the
// thread counts of either part.
TEST(RendererResume, CompletesTheUninterruptedPicture) {
    RecordingObserver full_observer;
    RenderStatistics full_statistics;
    const Film full = render_with(full_observer, 2, full_statistics);

    RecordingObserver stopping(3);
    RenderStatistics part_statistics;
    const Film part = render_with(stopping, 1, part_statistics);
    ASSERT_EQ(part.first_finished_row(), kWindow.bottom - 2);

    RecordingObserver observer;
    observer.rows_before = 3;
    RenderStatistics statistics;
    const Film done = render_with(observer, 3, statistics, nullptr, &part);
    EXPECT_FALSE(statistics.interrupted);
    EXPECT_TRUE(done.complete());
    EXPECT_EQ(observer.rows.size(), static_cast<std::size_t>(kWindow.height() - 3));
    EXPECT_EQ(std::count(observer.rows.begin(), observer.rows.end(), kWindow.bottom), 0);
    EXPECT_EQ(done.data(), full.data());
}

}  // namespace
}  // namespace rt
