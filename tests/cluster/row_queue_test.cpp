// The pieces of a cluster run that need no MPI: the rows a process waits to render, shared by its
// threads, and the bytes its messages are packed into.
#include "rt/cluster/row_queue.h"

#include <atomic>
#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "rt/cluster/protocol.h"

#include <gtest/gtest.h>

namespace rt::cluster {
namespace {

TEST(RowQueue, HandsOutRowsInOrderThenNothingOnceClosed) {
    RowQueue queue;
    queue.push(7);
    queue.push(3);
    EXPECT_EQ(queue.waiting(), 2);
    EXPECT_EQ(queue.next_row(), 7);
    queue.close();
    EXPECT_TRUE(queue.closed());
    EXPECT_EQ(queue.next_row(), 3);  // closing keeps the rows already handed out
    EXPECT_EQ(queue.next_row(), std::nullopt);
}

TEST(RowQueue, AbandonDropsWaitingRowsAndWakesTheThreads) {
    RowQueue queue;
    std::atomic<int> woken{0};
    std::vector<std::thread> threads;
    for (int i = 0; i < 3; ++i) {
        threads.emplace_back([&] {
            while (queue.next_row()) {
            }
            ++woken;
        });
    }
    queue.push(1);
    queue.abandon();
    queue.push(2);  // too late: abandoned is final for the threads that asked
    for (std::thread& t : threads) {
        t.join();
    }
    EXPECT_EQ(woken, 3);
}

TEST(Packer, ValuesAndTextRoundTrip) {
    const std::vector<float> pixels{0.25f, 1.5f, -0.0f};
    const std::vector<std::byte> bytes = Packer()
                                             .put(std::int32_t{-4})
                                             .put(std::uint64_t{1} << 40)
                                             .put_all(std::span<const float>(pixels))
                                             .put_text("rank")
                                             .bytes;
    Unpacker in(bytes);
    std::int32_t y = 0;
    std::uint64_t samples = 0;
    ASSERT_TRUE(in.get(y));
    ASSERT_TRUE(in.get(samples));
    EXPECT_EQ(y, -4);
    EXPECT_EQ(samples, std::uint64_t{1} << 40);
    float value = 0;
    for (const float expected : pixels) {
        ASSERT_TRUE(in.get(value));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(value), std::bit_cast<std::uint32_t>(expected));
    }
    EXPECT_EQ(in.rest_as_text(), "rank");
    std::uint64_t too_big = 0;
    EXPECT_FALSE(in.get(too_big));  // four bytes left, not eight
}

}  // namespace
}  // namespace rt::cluster
