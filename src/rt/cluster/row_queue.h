// The rows a process has been handed and not yet started, shared by its worker threads.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

#include "rt/render/renderer.h"

namespace rt::cluster {

class RowQueue : public RowSource {
public:
    /// Blocks until a row comes or the queue is closed (then nothing).
    std::optional<int> next_row() override;

    void push(int y);
    /// No more rows: waiting and later calls of next_row() get nothing once the queue is empty.
    void close();
    /// Like close(), and the rows not yet started are dropped (a stopped run).
    void abandon();
    /// Rows handed out but not yet taken by a thread.
    int waiting() const;
    bool closed() const;

private:
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<int> rows_;
    bool closed_ = false;
};

}  // namespace rt::cluster
