// -ds, the "strike" check (manual, Appendix): every ray is traced by the spatial method and again
// the slow way, by brute force, and the answers compared. The spatial method's answer is the one
// returned (the picture is its own); differences are counted for a summary at the end, and with
// -dsp each is reported, with -dso together with the voxels its walk visited.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "rt/accel/accelerator.h"
#include "rt/accel/brute_force.h"

namespace rt {

struct StrikeOptions {
    bool print_each = false;    ///< -dsp: report every difference
    bool print_voxels = false;  ///< -dso: with each difference, the voxels visited
};

class StrikeCheck : public Accelerator {
public:
    /// `report` receives one message per difference (with -dsp or -dso); it is called from the
    /// rendering threads, one call at a time.
    StrikeCheck(const Scene& scene, std::unique_ptr<Accelerator> checked, StrikeOptions options,
                std::function<void(const std::string&)> report);
    std::string_view name() const override { return checked_->name(); }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;
    std::size_t memory_bytes() const override { return checked_->memory_bytes(); }

    std::uint64_t rays_checked() const { return rays_.load(); }
    std::uint64_t differences() const { return differences_.load(); }
    /// "strike check (-ds): N of M rays ... differ from brute force".
    std::string summary() const;

private:
    void report_difference(const std::string& what, const Ray& ray, Interval t) const;

    std::unique_ptr<Accelerator> checked_;
    BruteForce brute_;
    StrikeOptions options_;
    std::function<void(const std::string&)> report_;
    mutable std::atomic<std::uint64_t> rays_{0};
    mutable std::atomic<std::uint64_t> differences_{0};
};

}  // namespace rt
