// The check every exit-culling test ends with: the layer over brute force answers each ray as
// brute force does, nearest hit (t and polygon) and occlusion alike, and -de finds no ray it
// culled wrongly.
#pragma once

#include <optional>

#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/scene/scene.h"

#include <gtest/gtest.h>

namespace rt::test {

/// `rays`: anything with `ray` and `t` members (TestRay, SurfaceRay).
template <class Rays>
void expect_culling_equals_brute_force(const Scene& scene, const Rays& rays) {
    const BruteForce brute(scene);
    ExitCullingSettings settings;
    settings.check_culled = true;
    const ExitCulling culling(scene, make_brute_force(scene), settings);
    TraceCounters brute_counters;
    TraceCounters culling_counters;
    for (const auto& r : rays) {
        const std::optional<Hit> expected = brute.closest_hit(r.ray, r.t, brute_counters);
        const std::optional<Hit> got = culling.closest_hit(r.ray, r.t, culling_counters);
        ASSERT_EQ(expected.has_value(), got.has_value());
        if (expected) {
            EXPECT_EQ(expected->t, got->t);
            EXPECT_EQ(expected->polygon, got->polygon);
        }
        EXPECT_EQ(brute.occluded(r.ray, r.t, brute_counters),
                  culling.occluded(r.ray, r.t, culling_counters));
    }
    const ExitCullingStatistics statistics = culling.statistics();
    EXPECT_EQ(statistics.checked, culling_counters.culled_exits);
    EXPECT_EQ(statistics.violations, 0u);
    EXPECT_TRUE(statistics.first_violations.empty());
}

}  // namespace rt::test
