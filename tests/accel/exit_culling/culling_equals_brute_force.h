// The check every exit-culling test ends with: the layer over brute force answers each ray as
// brute force does, nearest hit (t and polygon) and occlusion alike, and -de finds no ray it
// culled wrongly.
#pragma once

#include <cstdint>
#include <optional>

#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/scene/scene.h"

#include <gtest/gtest.h>

namespace rt::test {

/// `rays`: anything with `ray` and `t` members (TestRay, SurfaceRay). Returns how many rays the
/// layer answered from their guards' exact tests (TraceCounters::guard_answers).
template <class Rays>
std::uint64_t expect_culling_equals_brute_force(const Scene& scene, const Rays& rays) {
    const BruteForce brute(scene);
    // Its own answers, culled and from the guards alone...
    const ExitCulling culling(scene, make_brute_force(scene));
    // ... and -de's checks of them, which answer with brute force's.
    ExitCullingSettings settings;
    settings.check_culled = true;
    const ExitCulling checking(scene, make_brute_force(scene), settings);
    TraceCounters brute_counters;
    TraceCounters culling_counters;
    TraceCounters checking_counters;
    for (const auto& r : rays) {
        const std::optional<Hit> expected = brute.closest_hit(r.ray, r.t, brute_counters);
        const std::optional<Hit> got = culling.closest_hit(r.ray, r.t, culling_counters);
        EXPECT_EQ(expected.has_value(), got.has_value());
        if (expected && got) {
            EXPECT_EQ(expected->t, got->t);
            EXPECT_EQ(expected->polygon, got->polygon);
        }
        const bool blocked = brute.occluded(r.ray, r.t, brute_counters);
        EXPECT_EQ(blocked, culling.occluded(r.ray, r.t, culling_counters));
        checking.closest_hit(r.ray, r.t, checking_counters);
        EXPECT_EQ(blocked, checking.occluded(r.ray, r.t, checking_counters));
    }
    const ExitCullingStatistics statistics = checking.statistics();
    EXPECT_EQ(statistics.checked, checking_counters.culled_exits);
    EXPECT_EQ(statistics.violations, 0u);
    EXPECT_EQ(statistics.guards_checked, checking_counters.guard_answers);
    EXPECT_EQ(statistics.guard_violations, 0u);
    EXPECT_TRUE(statistics.first_violations.empty());
    return culling_counters.guard_answers;
}

}  // namespace rt::test
