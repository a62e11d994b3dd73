// Jobs of known size run by a fixed number of threads, the largest waiting job first. The BVH's
// build hands it the subtrees below its top: given a thread each, twenty of them shared two cores,
// each was descheduled every few milliseconds, and their working sets chased each other out of the
// caches. With as many threads as cores each runs to its end; largest first, the last to finish
// is a small one, so the threads also finish close together.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <queue>
#include <thread>
#include <vector>

namespace rt {

class LargestFirstQueue {
public:
    /// `workers` threads of its own, started when the first job is pushed (0: jobs run only in
    /// finish(), on the calling thread).
    explicit LargestFirstQueue(unsigned workers) : workers_(workers) {}
    LargestFirstQueue(const LargestFirstQueue&) = delete;
    LargestFirstQueue& operator=(const LargestFirstQueue&) = delete;
    /// Drops the jobs not started yet and waits for the running ones (an exception is leaving the
    /// owner, whose state the jobs use).
    ~LargestFirstQueue();

    /// Queues `job`, which must not throw (a job keeps its own exception for its owner). Jobs of
    /// equal size run in the order pushed.
    void push(std::uint64_t size, std::function<void()> job);

    /// Runs queued jobs on the calling thread too, and returns when every job pushed so far has
    /// finished.
    void finish();

private:
    struct Waiting {
        std::uint64_t size;
        std::uint64_t order;  ///< the push's number: among equal sizes, the earlier first
        std::function<void()> job;
        bool operator<(const Waiting& other) const {
            return size != other.size ? size < other.size : order > other.order;
        }
    };

    /// Takes the largest waiting job and runs it with the lock released; false if none waits.
    bool run_one(std::unique_lock<std::mutex>& lock);
    void work();

    unsigned workers_;
    std::mutex mutex_;
    std::condition_variable job_or_stop_;
    std::condition_variable job_done_;
    std::priority_queue<Waiting> waiting_;
    std::uint64_t pushed_ = 0;
    std::uint64_t running_ = 0;
    bool stopping_ = false;
    std::vector<std::thread> threads_;
};

}  // namespace rt
