#include "rt/accel/largest_first_queue.h"

#include <utility>

namespace rt {

LargestFirstQueue::~LargestFirstQueue() {
    {
        const std::lock_guard<std::mutex> hold(mutex_);
        stopping_ = true;
        waiting_ = {};
    }
    job_or_stop_.notify_all();
    for (std::thread& t : threads_) {
        t.join();
    }
}

void LargestFirstQueue::push(std::uint64_t size, std::function<void()> job) {
    {
        const std::lock_guard<std::mutex> hold(mutex_);
        waiting_.push({size, pushed_++, std::move(job)});
        if (threads_.empty()) {
            threads_.reserve(workers_);
            for (unsigned w = 0; w < workers_; ++w) {
                threads_.emplace_back([this] { work(); });
            }
        }
    }
    job_or_stop_.notify_one();
}

bool LargestFirstQueue::run_one(std::unique_lock<std::mutex>& lock) {
    if (waiting_.empty()) {
        return false;
    }
    // top() is const: the job is copied out before the pop (a function object, cheap).
    std::function<void()> job = waiting_.top().job;
    waiting_.pop();
    ++running_;
    lock.unlock();
    job();
    lock.lock();
    --running_;
    job_done_.notify_all();
    return true;
}

void LargestFirstQueue::work() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopping_) {
        if (!run_one(lock)) {
            job_or_stop_.wait(lock, [this] { return stopping_ || !waiting_.empty(); });
        }
    }
}

void LargestFirstQueue::finish() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        if (run_one(lock)) {
            continue;
        }
        if (running_ == 0) {
            return;
        }
        job_done_.wait(lock);
    }
}

}  // namespace rt
