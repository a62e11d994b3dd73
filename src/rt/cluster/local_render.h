// This process's share of a cluster render: a thread running the renderer over the rows pushed
// into its queue, with the finished rows collected for the thread that talks MPI.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "rt/cluster/row_queue.h"
#include "rt/render/renderer.h"

namespace rt::cluster {

struct FinishedRow {
    int y = 0;
    std::uint64_t samples = 0;
    std::vector<float> pixels;  ///< the window's width, three linear floats each
};

class LocalRender {
public:
    /// Starts rendering at once, with settings.threads threads, the rows that rows() receives.
    LocalRender(const Scene& scene, const Accelerator& accel, const RenderSettings& settings);
    /// Stops and waits for the threads.
    ~LocalRender();
    LocalRender(const LocalRender&) = delete;
    LocalRender& operator=(const LocalRender&) = delete;

    RowQueue& rows() { return queue_; }
    /// The rows finished since the last call.
    std::vector<FinishedRow> take_finished();
    /// Whether the renderer has returned (its queue closed and empty, or stopped).
    bool done() const { return done_; }
    /// Whether the renderer has ended with an error (join() rethrows it).
    bool failed() const { return done_ && error_ != nullptr; }
    /// Drops the rows not yet started; the threads finish their current row and end.
    void stop();
    /// Waits for the renderer; rethrows what it threw. The statistics are its own rows'.
    RenderStatistics join();
    /// Rows to keep waiting so that no thread idles while more are asked for.
    int threads() const { return threads_; }

private:
    class Collector : public RenderObserver {
    public:
        explicit Collector(LocalRender& owner) : owner_(owner) {}
        void row_done(const RowDone& row) override;
        bool should_stop() override { return owner_.stopping_; }

    private:
        LocalRender& owner_;
    };

    RowQueue queue_;
    RenderSettings settings_;
    Collector collector_{*this};
    std::mutex finished_mutex_;
    std::vector<FinishedRow> finished_;
    std::atomic<bool> stopping_{false};
    std::atomic<bool> done_{false};
    RenderStatistics statistics_;
    std::exception_ptr error_;
    int threads_ = 1;
    std::thread thread_;
};

}  // namespace rt::cluster
