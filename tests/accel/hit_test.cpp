// The one order of hits every method answers by (hit.h): nearer first, at equal t the lower id,
// whatever order the polygons are met in.
#include "rt/accel/hit.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>

namespace rt::test {
namespace {

TEST(HitOrder, NearerFirstThenLowerId) {
    EXPECT_TRUE(comes_before({1.0, 7}, {2.0, 3}));
    EXPECT_FALSE(comes_before({2.0, 3}, {1.0, 7}));
    EXPECT_TRUE(comes_before({1.0, 3}, {1.0, 7}));
    EXPECT_FALSE(comes_before({1.0, 7}, {1.0, 3}));
    EXPECT_FALSE(comes_before({1.0, 3}, {1.0, 3}));
}

TEST(ClosestHitSoFar, KeepsTheFirstHitInEveryOrderOfOffers) {
    std::array<Hit, 5> hits{{{3.0, 4}, {2.0, 9}, {2.0, 5}, {2.5, 1}, {2.0, 6}}};
    std::sort(hits.begin(), hits.end(),
              [](const Hit& a, const Hit& b) { return a.polygon < b.polygon; });
    do {
        ClosestHitSoFar nearest({0.0, 10.0});
        for (const Hit& h : hits) {
            nearest.offer(h.t, h.polygon);
        }
        ASSERT_TRUE(nearest.best());
        EXPECT_EQ(nearest.best()->t, 2.0);
        EXPECT_EQ(nearest.best()->polygon, 5u);
    } while (std::next_permutation(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
        return a.polygon < b.polygon;
    }));
}

TEST(ClosestHitSoFar, AsksUpToAndIncludingTheBestT) {
    ClosestHitSoFar nearest({0.5, 10.0});
    EXPECT_EQ(nearest.search_interval().min, 0.5);
    EXPECT_EQ(nearest.search_interval().max, 10.0);
    EXPECT_EQ(nearest.reach(), 10.0);
    nearest.offer(4.0, 2);
    // The interval is open: its top must lie just above 4 for a hit at 4 to come back.
    EXPECT_EQ(nearest.search_interval().min, 0.5);
    EXPECT_GT(nearest.search_interval().max, 4.0);
    EXPECT_EQ(nearest.search_interval().max, std::nextafter(4.0, 5.0));
    EXPECT_EQ(nearest.reach(), 4.0);
}

}  // namespace
}  // namespace rt::test
