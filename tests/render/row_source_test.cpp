// A pixel renders the same whatever else is rendered: rows from a RowSource, in any order, and a
// band of the window (rt --tile, a cluster's rows) hold exactly the whole render's bits.
#include <mutex>
#include <optional>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/render/renderer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr PixelRect kWindow{2, 3, 9, 12};  // 8 columns, 10 rows

// A lit box, three by three jittered samples a pixel: every pixel draws random numbers.
Scene sampled_box() {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, false);
    scene.view.look = {0, 0, 0};
    scene.view.sample_resolution_x = 3;
    scene.view.sample_resolution_y = 3;
    scene.attributes[0].color = {0.8, 0.6, 0.4};
    scene.attributes[0].emission = 0.5;
    scene.attributes[0].diffuse = 0.5;
    return scene;
}

// Hands out the given rows, in their order, to any thread.
class ListedRows : public RowSource {
public:
    explicit ListedRows(std::vector<int> rows) : rows_(std::move(rows)) {}
    std::optional<int> next_row() override {
        std::lock_guard lock(mutex_);
        if (next_ == rows_.size()) {
            return std::nullopt;
        }
        return rows_[next_++];
    }

private:
    std::mutex mutex_;
    std::vector<int> rows_;
    std::size_t next_ = 0;
};

Film render_rows(const PixelRect& window, RowSource* rows, int threads) {
    const Scene scene = sampled_box();
    const BruteForce accel(scene);
    RenderSettings settings;
    settings.window = window;
    settings.threads = threads;
    settings.shading.sampling.seed = 11;
    settings.rows = rows;
    RenderObserver observer;
    RenderStatistics statistics;
    return render(scene, accel, settings, observer, statistics);
}

void expect_same_row(const Film& a, const Film& b, int y) {
    for (int x = kWindow.left; x <= kWindow.right; ++x) {
        const Rgb p = a.pixel(x, y);
        const Rgb q = b.pixel(x, y);
        EXPECT_TRUE(p.r == q.r && p.g == q.g && p.b == q.b) << "pixel " << x << " " << y;
    }
}

TEST(RowSource, ListedRowsInAnyOrderAreTheWholeRendersBits) {
    const Film whole = render_rows(kWindow, nullptr, 2);
    ListedRows rows({5, 12, 3, 8});
    const Film some = render_rows(kWindow, &rows, 3);
    for (const int y : {5, 12, 3, 8}) {
        expect_same_row(whole, some, y);
    }
    // A pixel the source never handed out stays black.
    const Rgb untouched = some.pixel(kWindow.left, 4);
    EXPECT_EQ(untouched.r + untouched.g + untouched.b, 0.0);
    EXPECT_NE(whole.pixel(kWindow.left + 3, 5).r, 0.0);  // the box is in the picture
}

TEST(RowSource, ABandOfTheWindowIsTheWholeRendersBits) {
    const Film whole = render_rows(kWindow, nullptr, 1);
    const PixelRect band{kWindow.left, 6, kWindow.right, 9};
    const Film part = render_rows(band, nullptr, 2);
    for (int y = band.top; y <= band.bottom; ++y) {
        expect_same_row(whole, part, y);
    }
}

}  // namespace
}  // namespace rt
