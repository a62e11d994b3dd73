// Rays that start on polygons, the rays a renderer traces most: reflected and refracted rays
// leaving a hit point, and shadow feelers from it towards a light. They start within rounding of
// a polygon's plane, so every method must skip the polygon they leave (t below the renderer's
// self-intersection epsilon) and still find a neighbour a hair away.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/core/ray.h"
#include "rt/geometry/ray_polygon.h"
#include "rt/scene/scene.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

namespace rt::test {

/// The renderer's self-intersection epsilon (scene_epsilon in src/rt/render/ray_tracer.cpp):
/// hits nearer than 1e-9 of the scene's diagonal (at least 1e-9) belong to the surface left.
inline double renderer_epsilon(const Scene& scene) {
    const auto [lo, hi] = scene.bounds();
    return 1e-9 * std::max(1.0, length(hi - lo));
}

/// A point of polygon `id` in its plane: uniform over a triangle of the fan from its first corner,
/// the triangle picked by area (inside the polygon when it is convex).
inline Vec3 point_in_fan(const Scene& scene, std::uint32_t id, std::mt19937_64& rng) {
    const Polygon& p = scene.polygons[id];
    const Vec3 a = scene.corner_position(p, 0);
    std::vector<double> areas;
    for (std::uint32_t k = 1; k + 1 < p.corner_count; ++k) {
        areas.push_back(
            length(cross(scene.corner_position(p, k) - a, scene.corner_position(p, k + 1) - a)));
    }
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::uint32_t k = 1 + static_cast<std::uint32_t>(std::discrete_distribution<int>(
                                    areas.begin(), areas.end())(rng));
    const Vec3 b = scene.corner_position(p, k);
    const Vec3 c = scene.corner_position(p, k + 1);
    // Uniform on the triangle: fold the unit square's upper half back onto the lower one.
    double u = unit(rng);
    double v = unit(rng);
    if (u + v > 1.0) {
        u = 1.0 - u;
        v = 1.0 - v;
    }
    return a + (b - a) * u + (c - a) * v;
}

enum class SurfaceRayKind {
    Leaving,   ///< a unit direction into the half-space the polygon's normal points to
    Entering,  ///< a unit direction into the other half-space (a refracted ray)
    Feeler,    ///< towards a point of the scene's box, over (eps/d, 1 - eps/d) as feelers are
};

struct SurfaceRay {
    Ray ray;
    Interval t;
    std::uint32_t from = 0;  ///< the polygon it starts on (hand-made rays may leave it 0)
    SurfaceRayKind kind = SurfaceRayKind::Leaving;
    bool on_edge = false;  ///< starts on an edge or a corner, shared with a neighbour
};

/// A point of a random edge of polygon `id`, a corner one time in four.
inline Vec3 point_on_edge(const Scene& scene, std::uint32_t id, std::mt19937_64& rng) {
    const Polygon& p = scene.polygons[id];
    std::uniform_int_distribution<std::uint32_t> corner(0, p.corner_count - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::uint32_t k = corner(rng);
    const Vec3 a = scene.corner_position(p, k);
    const Vec3 b = scene.corner_position(p, (k + 1) % p.corner_count);
    return unit(rng) < 0.25 ? a : a + (b - a) * unit(rng);
}

/// `count` rays from random points of random polygons. A quarter start at a point of a polygon's
/// fan (point_in_fan), a quarter on its edges and corners (point_on_edge); half where an eye ray
/// from outside the scene's box, aimed at a point of a fan, first hits (origin + t * direction,
/// as the renderer computes a hit point; `from` is then the polygon hit). Directions: leaving or
/// entering at random angles (a tenth of them within about a degree of the plane), the mirror of
/// the eye ray or the eye ray going straight on, or a feeler. Half name `from` as the polygon
/// they leave (Ray::leaves).
inline std::vector<SurfaceRay> surface_rays(const Scene& scene, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::uint32_t> polygon(
        0, static_cast<std::uint32_t>(scene.polygons.size() - 1));
    const auto [lo, hi] = scene.bounds();
    const Vec3 centre = lo * 0.5 + hi * 0.5;
    const double diagonal = length(hi - lo);
    const double epsilon = renderer_epsilon(scene);
    const BruteForce brute(scene);
    TraceCounters counters;
    std::vector<SurfaceRay> rays;
    rays.reserve(count);
    while (static_cast<int>(rays.size()) < count) {
        SurfaceRay r;
        r.from = polygon(rng);
        Vec3 incoming;
        const Vec3 target = point_in_fan(scene, r.from, rng);
        if (rays.size() % 4 == 0) {
            r.ray.origin = target;
        } else if (rays.size() % 4 == 2) {
            r.ray.origin = point_on_edge(scene, r.from, rng);
            r.on_edge = true;
        } else {
            const Vec3 eye = centre + random_direction(rng) * diagonal * (0.6 + unit(rng));
            incoming = target - eye;
            const std::optional<Hit> hit = brute.closest_hit({eye, incoming}, {}, counters);
            if (!hit) {
                continue;  // aimed at a corner it slipped past; draw again
            }
            r.ray.origin = eye + incoming * hit->t;
            r.from = hit->polygon;
            incoming = normalize(incoming);
        }
        const Vec3 n = scene.polygons[r.from].normal;
        r.t = Interval{epsilon, kBeyondAnyScene};
        const int choice = static_cast<int>(unit(rng) * 10);
        if (choice < 6 || length(incoming) == 0.0) {
            Vec3 d = random_direction(rng);
            if (choice == 0) {  // nearly in the plane
                d = normalize(d - n * (dot(d, n) * (1.0 - 0.02 * unit(rng))));
            }
            const bool leaving = unit(rng) < 0.5;
            if ((dot(d, n) > 0.0) != leaving) {
                d = d - n * (2.0 * dot(d, n));
            }
            r.ray.direction = d;
            r.kind = leaving ? SurfaceRayKind::Leaving : SurfaceRayKind::Entering;
        } else if (choice < 8) {
            r.ray.direction = choice == 6 ? incoming - n * (2.0 * dot(incoming, n)) : incoming;
            r.kind =
                dot(r.ray.direction, n) > 0.0 ? SurfaceRayKind::Leaving : SurfaceRayKind::Entering;
        } else {
            const Vec3 light = random_point(rng, lo, hi);
            const double distance = length(light - r.ray.origin);
            if (!(distance > 2 * epsilon)) {
                continue;
            }
            r.ray.direction = light - r.ray.origin;
            r.t = Interval{epsilon / distance, 1.0 - epsilon / distance};
            r.kind = SurfaceRayKind::Feeler;
        }
        // Half of them say which polygon they leave, as the renderer's rays do (Ray::leaves):
        // every method must skip it as brute force does. The other half test the epsilon alone.
        if (rays.size() % 8 >= 4) {
            r.ray.leaves = r.from;
        }
        rays.push_back(r);
    }
    return rays;
}

/// Rays leaving a polygon's inside within 1e-8 of edge-on, from a rounding below its plane and
/// rising through it: the exact test gives many of them their own polygon back, at a grazing depth
/// beyond the epsilon. Each names that polygon as the one it leaves (Ray::leaves).
inline std::vector<SurfaceRay> grazing_surface_rays(const Scene& scene, int count,
                                                    std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::uint32_t> polygon(
        0, static_cast<std::uint32_t>(scene.polygons.size() - 1));
    const auto [lo, hi] = scene.bounds();
    const double size = std::max(1.0, length(hi - lo));
    std::vector<SurfaceRay> rays;
    while (static_cast<int>(rays.size()) < count) {
        SurfaceRay r;
        r.from = polygon(rng);
        const Vec3 n = scene.polygons[r.from].normal;
        const Vec3 along = cross(n, random_direction(rng));
        if (!(length(along) > 0.1)) {
            continue;
        }
        r.ray.origin = point_in_fan(scene, r.from, rng) - n * (1e-12 * size);
        r.ray.direction = normalize(along) + n * 1e-8;
        r.ray.leaves = r.from;
        r.t = Interval{renderer_epsilon(scene), kBeyondAnyScene};
        rays.push_back(r);
    }
    return rays;
}

/// What brute force, or a method, answers for one ray.
struct Answer {
    std::optional<Hit> hit;
    bool occluded = false;
};

/// How a ray's nearest hit is asked for: as any ray's, or through the eye-ray entry point.
enum class AskedAs { AnyRay, EyeRay };

/// closest_hit (or eye_ray_closest_hit) and occluded for the ray.
inline Answer answer_of(const Accelerator& accel, const SurfaceRay& r, TraceCounters& counters,
                        AskedAs asked = AskedAs::AnyRay) {
    return {asked == AskedAs::EyeRay ? accel.eye_ray_closest_hit(r.ray, r.t, counters)
                                     : accel.closest_hit(r.ray, r.t, counters),
            accel.occluded(r.ray, r.t, counters)};
}

/// The answers for every ray, in order.
inline std::vector<Answer> answers_of(const Accelerator& accel,
                                      const std::vector<SurfaceRay>& rays) {
    TraceCounters counters;
    std::vector<Answer> answers;
    answers.reserve(rays.size());
    for (const SurfaceRay& r : rays) {
        answers.push_back(answer_of(accel, r, counters));
    }
    return answers;
}

/// The ray and both answers, to reproduce a difference.
inline std::string describe(const SurfaceRay& r, const Answer& want, const Answer& got) {
    std::ostringstream s;
    s.precision(17);
    s << "from polygon " << r.from << " origin (" << r.ray.origin.x << ", " << r.ray.origin.y
      << ", " << r.ray.origin.z << ") direction (" << r.ray.direction.x << ", " << r.ray.direction.y
      << ", " << r.ray.direction.z << ") t (" << r.t.min << ", " << r.t.max << "): brute "
      << (want.hit ? std::to_string(want.hit->polygon) : "miss") << " t "
      << (want.hit ? want.hit->t : 0.0) << " occluded " << want.occluded << ", got "
      << (got.hit ? std::to_string(got.hit->polygon) : "miss") << " t "
      << (got.hit ? got.hit->t : 0.0) << " occluded " << got.occluded;
    return s.str();
}

/// Whether `got` is brute force's answer `want`: the same occlusion, hit or miss, t bits and
/// polygon; or, not `exact` (-on), the same occlusion and hit or miss and a real hit no nearer.
inline bool agrees(const Scene& scene, const SurfaceRay& r, const Answer& want, const Answer& got,
                   bool exact) {
    if (want.occluded != got.occluded || want.hit.has_value() != got.hit.has_value()) {
        return false;
    }
    if (!want.hit) {
        return true;
    }
    if (exact) {
        return want.hit->t == got.hit->t && want.hit->polygon == got.hit->polygon;
    }
    // A real hit on the polygon named, never nearer than the nearest.
    return got.hit->t >= want.hit->t &&
           intersect_polygon(r.ray, scene.polygon_view(got.hit->polygon), r.t) == got.hit->t;
}

/// Expects `accel` to give the answers brute force gave (`want`, one per ray): exactly, or with
/// `exact` false as -on may (see agrees). Reports the first few differences.
inline void expect_answers(const Scene& scene, const Accelerator& accel,
                           const std::vector<SurfaceRay>& rays, const std::vector<Answer>& want,
                           bool exact = true, AskedAs asked = AskedAs::AnyRay) {
    TraceCounters counters;
    int differences = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Answer got = answer_of(accel, rays[i], counters, asked);
        if (!agrees(scene, rays[i], want[i], got, exact) && ++differences <= 3) {
            ADD_FAILURE() << accel.name() << " differs " << describe(rays[i], want[i], got);
        }
    }
    EXPECT_EQ(differences, 0) << accel.name() << ", of " << rays.size() << " rays";
}

/// How many of the answers are hits.
inline int hits_in(const std::vector<Answer>& answers) {
    return static_cast<int>(
        std::count_if(answers.begin(), answers.end(), [](const Answer& a) { return a.hit; }));
}

}  // namespace rt::test
