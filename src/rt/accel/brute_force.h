// Brute force (.scn header "0 0", manual 1.3 and 3.1): every ray is tested against every polygon.
// The reference every other intersection method must agree with, so it is kept plain. It counts
// polygon tests only: the caller counts its rays and hits.
#pragma once

#include <memory>

#include "rt/accel/accelerator.h"

namespace rt {

class BruteForce : public Accelerator {
public:
    /// Keeps a reference to the scene, which must outlive it.
    explicit BruteForce(const Scene& scene) : scene_(scene) {}
    std::string_view name() const override { return "brute force"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;

private:
    const Scene& scene_;
};

std::unique_ptr<Accelerator> make_brute_force(const Scene& scene);

}  // namespace rt
