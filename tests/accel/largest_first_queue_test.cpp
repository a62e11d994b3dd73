#include "rt/accel/largest_first_queue.h"

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(LargestFirstQueue, WithoutWorkersFinishRunsLargestFirstThenInPushOrder) {
    LargestFirstQueue queue(0);
    std::vector<int> ran;
    const auto job = [&ran](int name) { return [&ran, name] { ran.push_back(name); }; };
    queue.push(5, job(1));
    queue.push(9, job(2));
    queue.push(5, job(3));
    queue.push(1, job(4));
    queue.push(9, job(5));
    EXPECT_TRUE(ran.empty()) << "no worker: nothing runs before finish()";
    queue.finish();
    EXPECT_EQ(ran, (std::vector<int>{2, 5, 1, 3, 4}));
}

TEST(LargestFirstQueue, FinishReturnsOnlyWhenEveryJobHasRun) {
    for (const unsigned workers : {1u, 3u, 8u}) {
        LargestFirstQueue queue(workers);
        std::atomic<int> done{0};
        std::mutex lock;
        std::vector<int> ran;
        for (int i = 0; i < 200; ++i) {
            queue.push(static_cast<std::uint64_t>(i % 7), [&, i] {
                if (i % 50 == 0) {
                    std::this_thread::sleep_for(std::chrono::milliseconds(2));
                }
                const std::lock_guard<std::mutex> hold(lock);
                ran.push_back(i);
                ++done;
            });
        }
        queue.finish();
        EXPECT_EQ(done.load(), 200) << workers << " workers";
        std::vector<bool> seen(200, false);
        for (const int i : ran) {
            EXPECT_FALSE(seen[static_cast<std::size_t>(i)]) << "job " << i << " ran twice";
            seen[static_cast<std::size_t>(i)] = true;
        }
    }
}

TEST(LargestFirstQueue, CanBeFinishedAgainAfterMorePushes) {
    LargestFirstQueue queue(2);
    std::atomic<int> done{0};
    queue.push(1, [&done] { ++done; });
    queue.finish();
    EXPECT_EQ(done.load(), 1);
    queue.push(1, [&done] { ++done; });
    queue.push(2, [&done] { ++done; });
    queue.finish();
    EXPECT_EQ(done.load(), 3);
}

TEST(LargestFirstQueue, DestroyedUnfinishedWaitsForRunningJobsAndDropsTheRest) {
    std::atomic<int> started{0};
    std::atomic<int> finished{0};
    {
        LargestFirstQueue queue(1);
        for (int i = 0; i < 100; ++i) {
            queue.push(1, [&] {
                ++started;
                std::this_thread::sleep_for(std::chrono::milliseconds(3));
                ++finished;
            });
        }
        while (started.load() == 0) {
            std::this_thread::yield();
        }
    }
    EXPECT_EQ(started.load(), finished.load()) << "a job was cut off while running";
    EXPECT_GE(finished.load(), 1);
    EXPECT_LT(finished.load(), 100) << "the waiting jobs should have been dropped";
}

}  // namespace
}  // namespace rt
