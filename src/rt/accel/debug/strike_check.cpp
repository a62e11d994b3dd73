#include "rt/accel/debug/strike_check.h"

#include <mutex>

#include "rt/accel/debug/describe_walk.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::string describe_hit(const std::optional<Hit>& hit) {
    return hit ? fmt::format("polygon {} at t {}", hit->polygon, hit->t) : "nothing";
}

bool same(const std::optional<Hit>& a, const std::optional<Hit>& b) {
    return a.has_value() == b.has_value() && (!a || (a->t == b->t && a->polygon == b->polygon));
}

}  // namespace

StrikeCheck::StrikeCheck(const Scene& scene, std::unique_ptr<Accelerator> checked,
                         StrikeOptions options, std::function<void(const std::string&)> report)
    : checked_(std::move(checked)), brute_(scene), options_(options), report_(std::move(report)) {}

std::optional<Hit> StrikeCheck::closest_hit(const Ray& ray, Interval t,
                                            TraceCounters& counters) const {
    const std::optional<Hit> hit = checked_->closest_hit(ray, t, counters);
    TraceCounters slow;  // brute force's work is the check's, not the method's
    const std::optional<Hit> want = brute_.closest_hit(ray, t, slow);
    ++rays_;
    if (!same(hit, want)) {
        report_difference(fmt::format("{} found {}, brute force {}", checked_->name(),
                                      describe_hit(hit), describe_hit(want)),
                          ray, t);
    }
    return hit;
}

bool StrikeCheck::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    const bool blocked = checked_->occluded(ray, t, counters);
    TraceCounters slow;
    const bool want = brute_.occluded(ray, t, slow);
    ++rays_;
    if (blocked != want) {
        report_difference(fmt::format("shadow feeler: {} says {}, brute force {}", checked_->name(),
                                      blocked ? "blocked" : "clear", want ? "blocked" : "clear"),
                          ray, t);
    }
    return blocked;
}

void StrikeCheck::report_difference(const std::string& what, const Ray& ray, Interval t) const {
    ++differences_;
    if (!options_.print_each && !options_.print_voxels) {
        return;
    }
    std::string message = fmt::format("strike: {} for the ray {}", what, describe_ray(ray, t));
    if (options_.print_voxels) {
        // fmt rather than string + string: GCC 12 warns falsely (-Wrestrict) on the latter here.
        const auto* walker = dynamic_cast<const DescribesWalk*>(checked_.get());
        message = fmt::format("{}\n{}", message,
                              walker != nullptr ? walker->describe_walk(ray, t)
                                                : "(no voxels: the method is not a voxel walk)");
    }
    static std::mutex one_at_a_time;
    const std::lock_guard<std::mutex> lock(one_at_a_time);
    report_(message);
}

std::string StrikeCheck::summary() const {
    return fmt::format(
        "strike check (-ds): {} of {} rays and shadow feelers differ from brute force",
        differences_.load(), rays_.load());
}

}  // namespace rt
