// Drawing one line into a film: one pixel a column (a row for a steep line), unbroken, every
// pixel one the line passes through, and a window showing the whole view's pixels.
#include "rt/wireframe/line_raster.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr Rgb kWhite{1.0, 1.0, 1.0};

std::set<std::pair<int, int>> drawn(const Film& film) {
    std::set<std::pair<int, int>> pixels;
    const PixelRect& w = film.window();
    for (int y = w.top; y <= w.bottom; ++y) {
        for (int x = w.left; x <= w.right; ++x) {
            if (film.pixel(x, y).r > 0.0) {
                pixels.insert({x, y});
            }
        }
    }
    return pixels;
}

// Whether the segment passes through the closed pixel square (x, y): some point of it inside.
bool crosses(const PixelSegment& s, int x, int y) {
    double t0 = 0.0;
    double t1 = 1.0;
    const double d[2] = {s.to.x - s.from.x, s.to.y - s.from.y};
    const double p[2] = {s.from.x, s.from.y};
    const double low[2] = {static_cast<double>(x), static_cast<double>(y)};
    for (int a = 0; a < 2; ++a) {
        if (d[a] == 0.0) {
            if (p[a] < low[a] || p[a] > low[a] + 1.0) {
                return false;
            }
            continue;
        }
        double enter = (low[a] - p[a]) / d[a];
        double leave = (low[a] + 1.0 - p[a]) / d[a];
        if (enter > leave) {
            std::swap(enter, leave);
        }
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
    }
    return t0 <= t1 + 1e-12;
}

TEST(LineRaster, AFlatLineIsOneRowFromEndToEnd) {
    Film film(16, 12, PixelRect{0, 0, 15, 11});
    draw_line(film, {{2.2, 5.5}, {9.7, 5.5}}, kWhite);
    std::set<std::pair<int, int>> expected;
    for (int x = 2; x <= 9; ++x) {
        expected.insert({x, 5});
    }
    EXPECT_EQ(drawn(film), expected);
    EXPECT_EQ(film.pixel(3, 5).g, 1.0);
}

TEST(LineRaster, ASteepLineIsOnePixelARow) {
    Film film(16, 12, PixelRect{0, 0, 15, 11});
    draw_line(film, {{4.5, 10.9}, {6.1, 1.2}}, kWhite);
    const std::set<std::pair<int, int>> pixels = drawn(film);
    EXPECT_EQ(pixels.size(), 10U);  // rows 1 to 10
    std::set<int> rows;
    for (const auto& [x, y] : pixels) {
        rows.insert(y);
    }
    EXPECT_EQ(rows.size(), pixels.size());
}

TEST(LineRaster, EveryPixelIsCrossedAndTheLineIsUnbroken) {
    std::mt19937 random(12);
    std::uniform_real_distribution<double> coordinate(0.0, 40.0);
    for (int trial = 0; trial < 500; ++trial) {
        Film film(40, 40, PixelRect{0, 0, 39, 39});
        const PixelSegment s{{coordinate(random), coordinate(random)},
                             {coordinate(random), coordinate(random)}};
        draw_line(film, s, kWhite);
        const std::set<std::pair<int, int>> pixels = drawn(film);
        ASSERT_FALSE(pixels.empty());
        for (const auto& [x, y] : pixels) {
            EXPECT_TRUE(crosses(s, x, y)) << trial << ": (" << x << ", " << y << ")";
        }
        // Both ends reach their pixels or the next one (the first column is drawn where the
        // line crosses its centre), and from each pixel a neighbour (8-connected) leads on.
        for (const PixelPoint& end : {s.from, s.to}) {
            const int ex = static_cast<int>(end.x);
            const int ey = static_cast<int>(end.y);
            EXPECT_TRUE(std::any_of(pixels.begin(), pixels.end(), [&](const auto& p) {
                return std::abs(p.first - ex) <= 1 && std::abs(p.second - ey) <= 1;
            })) << trial;
        }
        std::set<std::pair<int, int>> reached{*pixels.begin()};
        std::vector<std::pair<int, int>> pending{*pixels.begin()};
        while (!pending.empty()) {
            const auto [x, y] = pending.back();
            pending.pop_back();
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::pair next{x + dx, y + dy};
                    if (pixels.contains(next) && reached.insert(next).second) {
                        pending.push_back(next);
                    }
                }
            }
        }
        EXPECT_EQ(reached.size(), pixels.size()) << trial << ": the line is broken";
    }
}

TEST(LineRaster, PointsOnTheViewsFarEdgesBelongToItsLastPixels) {
    Film film(10, 8, PixelRect{0, 0, 9, 7});
    draw_line(film, {{0.0, 8.0}, {10.0, 8.0}}, kWhite);   // along the bottom edge
    draw_line(film, {{10.0, 0.0}, {10.0, 8.0}}, kWhite);  // along the right edge
    for (int x = 0; x <= 9; ++x) {
        EXPECT_GT(film.pixel(x, 7).r, 0.0) << x;
    }
    for (int y = 0; y <= 7; ++y) {
        EXPECT_GT(film.pixel(9, y).r, 0.0) << y;
    }
    EXPECT_EQ(drawn(film).size(), 17U);
}

// A window shows the whole view's pixels there, and nothing of the line outside it: the pixels
// are chosen over the whole view, so a line entering the window keeps its first pixels.
TEST(LineRaster, AWindowShowsExactlyTheWholeViewsPixels) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(0.0, 40.0);
    const PixelRect window{9, 13, 30, 25};
    for (int trial = 0; trial < 300; ++trial) {
        const PixelSegment s{{coordinate(random), coordinate(random)},
                             {coordinate(random), coordinate(random)}};
        Film whole(40, 40, PixelRect{0, 0, 39, 39});
        Film part(40, 40, window);
        draw_line(whole, s, kWhite);
        draw_line(part, s, kWhite);
        std::set<std::pair<int, int>> inside;
        for (const auto& [x, y] : drawn(whole)) {
            if (x >= window.left && x <= window.right && y >= window.top && y <= window.bottom) {
                inside.insert({x, y});
            }
        }
        EXPECT_EQ(drawn(part), inside) << trial;
    }
}

}  // namespace
}  // namespace rt
