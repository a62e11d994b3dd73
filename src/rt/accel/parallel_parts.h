// The builds' one way of using several cores (exit culling, the voxel methods' packets, the
// BVH's passes): a range cut into contiguous parts, one thread a part (run_in_parts), or into
// more pieces than threads, each thread taking the next when done with its last (share_out), so
// that a core slowed by another program holds no other back. Every pass that uses them writes
// either its own slots or its own copy that the caller merges by an exact, order-free operation
// (box union, bitwise or, maximum, sum of counts), so what it builds is the same bit for bit for
// any number of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace rt {

/// Below this many polygons a build runs on the calling thread: starting threads would cost more
/// than the whole build (twocubes' exit culling builds in about 2 ms).
inline constexpr std::size_t kPolygonsForThreadedBuilds = 20000;

/// One thread a core, at most 16.
inline int every_core() {
    return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
}

/// A build's thread count: `asked` if positive, else one a core, and 1 for small scenes.
inline int build_threads_for(int asked, std::size_t polygon_count) {
    if (asked > 0) {
        return std::min(asked, 64);
    }
    if (polygon_count < kPolygonsForThreadedBuilds) {
        return 1;
    }
    return every_core();
}

/// Calls work(begin, end, part) for `parts` contiguous parts of [0, count), part 0 on the calling
/// thread and each other part on a thread of its own; returns when all are done.
template <class Work>
void run_in_parts(std::size_t count, int parts, Work&& work) {
    const std::size_t n = static_cast<std::size_t>(std::max(parts, 1));
    if (n == 1) {
        work(std::size_t{0}, count, 0);
        return;
    }
    std::vector<std::jthread> pool;
    pool.reserve(n - 1);
    for (std::size_t part = 1; part < n; ++part) {
        pool.emplace_back([&work, count, n, part] {
            work(count * part / n, count * (part + 1) / n, static_cast<int>(part));
        });
    }
    work(std::size_t{0}, count / n, 0);
}

/// Calls work(i, thread) for every i in [0, count), on up to `threads` threads (the calling one
/// among them), each taking the next i when done with its last: for parts of uneven size.
/// `thread`, in [0, threads), is for scratch space of the thread's own.
template <class Work>
void share_out(std::size_t count, int threads, Work&& work) {
    const auto n = static_cast<int>(std::clamp<std::size_t>(
        static_cast<std::size_t>(std::max(threads, 1)), 1, std::max<std::size_t>(count, 1)));
    std::atomic<std::size_t> next{0};
    run_in_parts(static_cast<std::size_t>(n), n, [&](std::size_t, std::size_t, int thread) {
        for (std::size_t i = next++; i < count; i = next++) {
            work(i, thread);
        }
    });
}

}  // namespace rt
