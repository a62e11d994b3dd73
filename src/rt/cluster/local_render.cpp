#include "rt/cluster/local_render.h"

#include <algorithm>

namespace rt::cluster {

LocalRender::LocalRender(const Scene& scene, const Accelerator& accel,
                         const RenderSettings& settings)
    : settings_(settings) {
    settings_.rows = &queue_;
    threads_ = settings.threads > 0
                   ? settings.threads
                   : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    thread_ = std::thread([this, &scene, &accel] {
        try {
            (void)render(scene, accel, settings_, collector_, statistics_);
        } catch (...) {
            error_ = std::current_exception();
        }
        done_ = true;
    });
}

LocalRender::~LocalRender() {
    if (thread_.joinable()) {
        stop();
        thread_.join();
    }
}

void LocalRender::Collector::row_done(const RowDone& row) {
    FinishedRow finished{row.y, row.samples,
                         std::vector<float>(row.pixels.begin(), row.pixels.end())};
    std::lock_guard lock(owner_.finished_mutex_);
    owner_.finished_.push_back(std::move(finished));
}

std::vector<FinishedRow> LocalRender::take_finished() {
    std::lock_guard lock(finished_mutex_);
    std::vector<FinishedRow> rows;
    rows.swap(finished_);
    return rows;
}

void LocalRender::stop() {
    stopping_ = true;
    queue_.abandon();
}

RenderStatistics LocalRender::join() {
    if (thread_.joinable()) {
        thread_.join();
    }
    if (error_) {
        std::rethrow_exception(error_);
    }
    return statistics_;
}

}  // namespace rt::cluster
