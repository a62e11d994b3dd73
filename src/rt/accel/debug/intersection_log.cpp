#include "rt/accel/debug/intersection_log.h"

#include <mutex>

#include "rt/accel/debug/describe_walk.h"

#include <fmt/format.h>

namespace rt {

IntersectionLog::IntersectionLog(std::unique_ptr<Accelerator> logged,
                                 std::function<void(const std::string&)> print)
    : logged_(std::move(logged)), print_(std::move(print)) {}

std::optional<Hit> IntersectionLog::closest_hit(const Ray& ray, Interval t,
                                                TraceCounters& counters) const {
    const std::optional<Hit> hit = logged_->closest_hit(ray, t, counters);
    const std::string line =
        fmt::format("intersection: {} -> {}", describe_ray(ray, t),
                    hit ? fmt::format("polygon {} at t {}", hit->polygon, hit->t) : "nothing");
    static std::mutex one_at_a_time;
    const std::lock_guard<std::mutex> lock(one_at_a_time);
    print_(line);
    return hit;
}

}  // namespace rt
