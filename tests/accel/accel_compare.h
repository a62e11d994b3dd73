// Random rays for comparing an accelerator with brute force: rays from anywhere in the doubled
// bounding box in any direction, and rays aimed at polygons' corners, edges and insides (where
// watertightness and ties are decided), with assorted intervals.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/accel/brute_force.h"
#include "rt/core/bounds.h"

#include <gtest/gtest.h>

namespace rt::test {

struct RayQuery {
    Ray ray;
    Interval t;
};

/// The box around the scene's finite positions (a NaN or infinite corner would make every ray
/// built from it non-finite); a unit box at the origin when there are none.
inline Box3 finite_bounds(const Scene& scene) {
    Box3 box;
    for (const Vec3& p : scene.positions) {
        if (is_finite(p)) {
            box.add(p);
        }
    }
    if (box.empty()) {
        return {Vec3{-0.5, -0.5, -0.5}, Vec3{0.5, 0.5, 0.5}};
    }
    return box;
}

/// The box's largest side; for a box of one point, a size at the point's own scale.
inline double scene_size(const Box3& box) {
    const double size = box.largest_extent();
    return size > 0.0 ? size : std::max(box.magnitude(), 1e-300);
}

/// Rays whose origins fill the scene's box doubled on every side (padded by a twentieth of its
/// largest side, so that flat scenes get room and a scene of size 1e-30 is not lost in a fixed
/// pad), half in random directions and half aimed at polygons. Directions are scaled by the
/// scene's size, so the finite intervals below mean the same at every scale.
inline std::vector<RayQuery> random_queries(const Scene& scene, int count, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    const Box3 bounds = finite_bounds(scene);
    const Vec3 lo = bounds.lo;
    const Vec3 hi = bounds.hi;
    const double size = scene_size(bounds);
    const Vec3 middle = lo * 0.5 + hi * 0.5;  // not (lo + hi) / 2, which overflows near DBL_MAX
    const Vec3 pad{size / 20, size / 20, size / 20};
    const Vec3 half = (hi - lo) + pad;
    const auto anywhere = [&] {
        return middle + Vec3{half.x * (2 * unit(random) - 1), half.y * (2 * unit(random) - 1),
                             half.z * (2 * unit(random) - 1)};
    };
    const auto target = [&]() -> Vec3 {
        if (scene.polygons.empty()) {
            return anywhere();
        }
        const Polygon& p = scene.polygons[random() % scene.polygons.size()];
        const Vec3 a = scene.corner_position(p, random() % p.corner_count);
        const Vec3 b = scene.corner_position(p, random() % p.corner_count);
        switch (random() % 4) {
            case 0:
                return a;  // a corner
            case 1:
                return (a + b) * 0.5;  // an edge's middle (or a corner again)
            case 2:
                return a + (b - a) * unit(random);
            default: {
                const Vec3 c = scene.corner_position(p, random() % p.corner_count);
                const double u = unit(random);
                const double v = unit(random) * (1 - u);
                return a + (b - a) * u + (c - a) * v;
            }
        }
    };
    std::vector<RayQuery> queries;
    queries.reserve(count);
    for (int i = 0; i < count; ++i) {
        RayQuery q;
        q.ray.origin = anywhere();
        if (i % 2 == 0) {
            q.ray.direction = Vec3{normal(random), normal(random), normal(random)} * size;
        } else {
            q.ray.direction = (target() - q.ray.origin) * (0.5 + unit(random));
        }
        switch (i % 5) {
            case 0:
                q.t = Interval{};
                break;
            case 1:
                q.t = Interval{1e-9, kBeyondAnyScene};
                break;
            case 2:
                q.t = Interval{unit(random), 0.5 + 2 * unit(random)};
                break;
            case 3:
                q.t = Interval{-kBeyondAnyScene, kBeyondAnyScene};
                break;
            default:
                q.t = Interval{0.0, std::nextafter(1.0, 0.0)};  // up to the target, not at it
        }
        queries.push_back(q);
    }
    return queries;
}

/// Every query answered identically (t bits, polygon, occlusion) by both, and at least
/// `minimum_hit_share` of them hitting something: agreement on misses alone proves nothing.
/// Returns how many hit.
inline int expect_same_answers(const Scene& scene, const Accelerator& accel,
                               const std::vector<RayQuery>& queries,
                               double minimum_hit_share = 0.1) {
    const BruteForce brute(scene);
    TraceCounters counters;
    int mismatches = 0;
    int hits = 0;
    for (const RayQuery& q : queries) {
        const std::optional<Hit> want = brute.closest_hit(q.ray, q.t, counters);
        const std::optional<Hit> got = accel.closest_hit(q.ray, q.t, counters);
        hits += want.has_value() ? 1 : 0;
        const bool same = want.has_value() == got.has_value() &&
                          (!want || (want->t == got->t && want->polygon == got->polygon));
        const bool same_occlusion =
            brute.occluded(q.ray, q.t, counters) == accel.occluded(q.ray, q.t, counters);
        if ((!same || !same_occlusion) && ++mismatches <= 5) {
            ADD_FAILURE() << accel.name() << " differs: origin " << q.ray.origin.x << ' '
                          << q.ray.origin.y << ' ' << q.ray.origin.z << " direction "
                          << q.ray.direction.x << ' ' << q.ray.direction.y << ' '
                          << q.ray.direction.z << " t " << q.t.min << ".." << q.t.max << " brute "
                          << (want ? std::to_string(want->polygon) : "miss") << ' '
                          << (want ? want->t : 0.0) << " got "
                          << (got ? std::to_string(got->polygon) : "miss") << ' '
                          << (got ? got->t : 0.0) << (same_occlusion ? "" : " (occluded differs)");
        }
    }
    EXPECT_EQ(mismatches, 0) << "of " << queries.size() << " rays";
    EXPECT_GE(hits, minimum_hit_share * static_cast<double>(queries.size()))
        << accel.name() << ": only " << hits << " of " << queries.size()
        << " rays hit anything, too few for the comparison to mean much";
    return hits;
}

inline int compare_with_brute_force(const Scene& scene, const Accelerator& accel, int rays,
                                    std::uint64_t seed, double minimum_hit_share = 0.1) {
    return expect_same_answers(scene, accel, random_queries(scene, rays, seed), minimum_hit_share);
}

}  // namespace rt::test
