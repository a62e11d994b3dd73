// How the render threads share out the rows: in bands of neighbouring rows, bottom first. A
// thread that renders neighbouring rows finds the pixel centres its memo keeps (the adaptive
// rule's probes, renderer.cpp) still useful for the next row; rows handed out one at a time went
// to alternate threads, and each traced every row of centres twice over. The bands shrink as the
// rows run out, so that no thread is left with a long band at the end. Which thread renders which
// row does not change the picture.
#pragma once

#include <algorithm>
#include <atomic>

namespace rt {

/// Row indices [first, end), counted from the bottom; empty when every row is taken.
struct RowBand {
    int first = 0;
    int end = 0;
    bool empty() const { return first >= end; }
};

/// The most rows a band holds.
inline constexpr int kMostBandRows = 16;

/// Claims the next band of `rows` rows for one of `threads` threads: a quarter of a thread's share
/// of the rows left, 1 to kMostBandRows. `next` is the first row index not yet claimed.
inline RowBand claim_row_band(std::atomic<int>& next, int rows, int threads) {
    int start = next.load(std::memory_order_relaxed);
    int size = 1;
    do {
        if (start >= rows) {
            return {rows, rows};
        }
        size = std::clamp((rows - start) / (4 * std::max(threads, 1)), 1, kMostBandRows);
    } while (!next.compare_exchange_weak(start, start + size, std::memory_order_relaxed));
    return {start, std::min(start + size, rows)};
}

}  // namespace rt
