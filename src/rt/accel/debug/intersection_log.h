// -dl, "print intersections" (manual, Appendix): every nearest-hit query and its answer, one line
// each. The 1988 program printed only brute force's; this prints whatever method is in use.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "rt/accel/accelerator.h"

namespace rt {

class IntersectionLog : public Accelerator {
public:
    /// `print` is called from the rendering threads, one call at a time.
    IntersectionLog(std::unique_ptr<Accelerator> logged,
                    std::function<void(const std::string&)> print);
    std::string_view name() const override { return logged_->name(); }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return logged_->occluded(ray, t, counters);
    }
    std::size_t memory_bytes() const override { return logged_->memory_bytes(); }

private:
    std::unique_ptr<Accelerator> logged_;
    std::function<void(const std::string&)> print_;
};

}  // namespace rt
