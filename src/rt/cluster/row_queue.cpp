#include "rt/cluster/row_queue.h"

namespace rt::cluster {

std::optional<int> RowQueue::next_row() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !rows_.empty() || closed_; });
    if (rows_.empty()) {
        return std::nullopt;
    }
    const int y = rows_.front();
    rows_.pop_front();
    return y;
}

void RowQueue::push(int y) {
    {
        std::lock_guard lock(mutex_);
        rows_.push_back(y);
    }
    changed_.notify_one();
}

void RowQueue::close() {
    {
        std::lock_guard lock(mutex_);
        closed_ = true;
    }
    changed_.notify_all();
}

void RowQueue::abandon() {
    {
        std::lock_guard lock(mutex_);
        closed_ = true;
        rows_.clear();
    }
    changed_.notify_all();
}

int RowQueue::waiting() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(rows_.size());
}

bool RowQueue::closed() const {
    std::lock_guard lock(mutex_);
    return closed_;
}

}  // namespace rt::cluster
