// The render threads' rows: every row handed out once, in bands of neighbouring rows that shrink
// to single rows at the end, whatever the number of threads claiming them at once.
#include "rt/render/row_bands.h"

#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace rt::test {
namespace {

TEST(RowBands, OneThreadTakesEveryRowInOrderInShrinkingBands) {
    std::atomic<int> next{0};
    std::vector<int> sizes;
    int expected_first = 0;
    for (RowBand band = claim_row_band(next, 400, 1); !band.empty();
         band = claim_row_band(next, 400, 1)) {
        EXPECT_EQ(band.first, expected_first);
        sizes.push_back(band.end - band.first);
        expected_first = band.end;
    }
    EXPECT_EQ(expected_first, 400);
    ASSERT_FALSE(sizes.empty());
    EXPECT_EQ(sizes.front(), kMostBandRows);
    EXPECT_EQ(sizes.back(), 1);
    for (std::size_t k = 1; k < sizes.size(); ++k) {
        EXPECT_LE(sizes[k], sizes[k - 1]) << k;
    }
    EXPECT_TRUE(claim_row_band(next, 400, 1).empty());
}

TEST(RowBands, ManyThreadsOnFewRowsTakeThemOneAtATime) {
    std::atomic<int> next{0};
    for (int row = 0; row < 10; ++row) {
        const RowBand band = claim_row_band(next, 10, 64);
        EXPECT_EQ(band.first, row);
        EXPECT_EQ(band.end, row + 1);
    }
    EXPECT_TRUE(claim_row_band(next, 10, 64).empty());
}

TEST(RowBands, ResumedRowsAreNotHandedOutAgain) {
    std::atomic<int> next{395};
    const RowBand band = claim_row_band(next, 400, 2);
    EXPECT_EQ(band.first, 395);
    EXPECT_EQ(band.end, 396);
}

TEST(RowBands, ThreadsClaimingAtOnceGetEveryRowOnce) {
    constexpr int kRows = 5000;
    constexpr int kThreads = 4;
    std::atomic<int> next{0};
    std::vector<std::vector<int>> taken(kThreads);
    std::vector<std::thread> threads;
    threads.reserve(kThreads);
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&, t] {
            for (RowBand band = claim_row_band(next, kRows, kThreads); !band.empty();
                 band = claim_row_band(next, kRows, kThreads)) {
                for (int row = band.first; row < band.end; ++row) {
                    taken[static_cast<std::size_t>(t)].push_back(row);
                }
            }
        });
    }
    for (std::thread& thread : threads) {
        thread.join();
    }
    std::vector<int> count(kRows, 0);
    for (const std::vector<int>& rows : taken) {
        for (const int row : rows) {
            ++count[static_cast<std::size_t>(row)];
        }
    }
    for (int row = 0; row < kRows; ++row) {
        ASSERT_EQ(count[static_cast<std::size_t>(row)], 1) << row;
    }
}

}  // namespace
}  // namespace rt::test
