// Shared by the SEADS and octree tests: random scenes and rays, and the comparison of an
// accelerator with brute force over many rays (identical t bits and polygon, or both a miss).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/accel/brute_force.h"
#include "rt/accel/voxel/box.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt::test {

/// `count` triangles of random size (most small, some spanning much of the unit cube).
inline Scene random_triangle_soup(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    SceneBuilder b;
    for (int i = 0; i < count; ++i) {
        const double size = (i % 10 == 0) ? 0.8 : 0.05;
        const Vec3 a{unit(rng), unit(rng), unit(rng)};
        auto near = [&] {
            return a + Vec3{(unit(rng) - 0.5) * size, (unit(rng) - 0.5) * size,
                            (unit(rng) - 0.5) * size};
        };
        b.add_polygon({a, near(), near()});
    }
    return std::move(b.scene());
}

/// Rays of many kinds for a scene inside `world`: from outside and from inside, random and
/// axis-parallel and nearly so, with random intervals.
struct RayCase {
    Ray ray;
    Interval t;
};

inline std::vector<RayCase> random_rays(const Box3& world, int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    const Vec3 size = world.extent();
    auto point_in = [&](double grow) {
        return Vec3{world.lo.x - grow * size.x + (1 + 2 * grow) * size.x * unit(rng),
                    world.lo.y - grow * size.y + (1 + 2 * grow) * size.y * unit(rng),
                    world.lo.z - grow * size.z + (1 + 2 * grow) * size.z * unit(rng)};
    };
    std::vector<RayCase> rays;
    rays.reserve(count);
    for (int i = 0; i < count; ++i) {
        RayCase c;
        const int kind = i % 5;
        c.ray.origin = point_in(kind == 0 ? 1.0 : 0.0);
        Vec3 d{normal(rng), normal(rng), normal(rng)};
        if (kind == 2) {
            // Axis-parallel: exactly zero in two components.
            const int axis = i % 3;
            d = Vec3{};
            d[axis] = unit(rng) < 0.5 ? -1.0 : 1.0;
        } else if (kind == 3) {
            // Nearly axis-parallel.
            const int axis = i % 3;
            d[axis] = d[axis] < 0 ? -1e6 : 1e6;
        }
        c.ray.direction = d * (0.5 + unit(rng));
        if (i % 7 == 0) {
            c.t = Interval{0.3 * unit(rng), 0.5 + 2.0 * unit(rng)};
        }
        rays.push_back(c);
    }
    return rays;
}

inline std::string describe(const RayCase& c) {
    std::ostringstream s;
    s.precision(17);
    s << "origin (" << c.ray.origin.x << ", " << c.ray.origin.y << ", " << c.ray.origin.z
      << ") direction (" << c.ray.direction.x << ", " << c.ray.direction.y << ", "
      << c.ray.direction.z << ") t (" << c.t.min << ", " << c.t.max << ")";
    return s.str();
}

/// Expects closest_hit and occluded to agree exactly with brute force on every ray, and at least
/// `minimum_hit_share` of the rays to hit (agreement on misses proves little); reports the first
/// few differences. Returns the accelerator's counters.
inline TraceCounters expect_same_as_brute_force(const Scene& scene, const Accelerator& accel,
                                                const std::vector<RayCase>& rays,
                                                double minimum_hit_share = 0.03) {
    const BruteForce brute(scene);
    TraceCounters brute_counters;
    TraceCounters counters;
    int differences = 0;
    for (const RayCase& c : rays) {
        const std::optional<Hit> want = brute.closest_hit(c.ray, c.t, brute_counters);
        const std::optional<Hit> got = accel.closest_hit(c.ray, c.t, counters);
        const bool same = want.has_value() == got.has_value() &&
                          (!want || (want->t == got->t && want->polygon == got->polygon));
        counters.hits += got ? 1 : 0;
        const bool want_blocked = brute.occluded(c.ray, c.t, brute_counters);
        const bool blocked = accel.occluded(c.ray, c.t, counters);
        if ((!same || want_blocked != blocked) && ++differences <= 5) {
            ADD_FAILURE() << accel.name() << " differs from brute force for " << describe(c)
                          << ": brute " << (want ? std::to_string(want->polygon) : "miss") << " t "
                          << (want ? want->t : 0.0) << ", got "
                          << (got ? std::to_string(got->polygon) : "miss") << " t "
                          << (got ? got->t : 0.0) << "; occluded " << want_blocked << " vs "
                          << blocked;
        }
    }
    EXPECT_EQ(differences, 0) << "of " << rays.size() << " rays";
    EXPECT_GE(static_cast<double>(counters.hits),
              minimum_hit_share * static_cast<double>(rays.size()))
        << accel.name() << ": only " << counters.hits << " of " << rays.size()
        << " rays hit anything, too few for the comparison to mean much";
    return counters;
}

/// A lattice of voxel boundaries: plane k along an axis lies at lattice(axis, k), for k in
/// [0, divisions]. How the accelerator under test computes its own boundaries.
using Lattice = std::function<double(int axis, int k)>;

/// Two specks fixing the bounds at the unit cube, then quads lying exactly in interior voxel
/// faces of the lattice (corners on lattice points, so inside the bounds).
inline Scene unit_cube_anchors() {
    SceneBuilder b;
    b.add_polygon({{0, 0, 0}, {1e-3, 0, 0}, {0, 1e-3, 0}});
    b.add_polygon({{1, 1, 1}, {1 - 1e-3, 1, 1}, {1, 1 - 1e-3, 1}});
    return std::move(b.scene());
}

inline void add_lattice_faces(Scene& scene, const Lattice& lattice, int divisions, int count,
                              std::uint32_t seed) {
    SceneBuilder b;
    b.scene() = scene;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> inner(1, divisions - 2);
    std::uniform_int_distribution<int> plane(1, divisions - 1);
    for (int i = 0; i < count; ++i) {
        const int axis = i % 3;
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        const int k = plane(rng);
        const int j = inner(rng);
        const int l = inner(rng);
        auto corner = [&](int dj, int dl) {
            Vec3 c;
            c[axis] = lattice(axis, k);
            c[u] = lattice(u, j + dj);
            c[v] = lattice(v, l + dl);
            return c;
        };
        if (i % 2 == 0) {
            b.add_polygon({corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)});
        } else {
            b.add_polygon({corner(0, 0), corner(1, 0), corner(1, 1)});
        }
    }
    scene = std::move(b.scene());
}

/// Rays that start on lattice points and lines and run along voxel faces, edges and through
/// voxel corners, forwards and backwards.
inline std::vector<RayCase> lattice_rays(const Lattice& lattice, int divisions, int count,
                                         std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> point(0, divisions);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<RayCase> rays;
    for (int i = 0; i < count; ++i) {
        int k[3] = {point(rng), point(rng), point(rng)};
        RayCase c;
        for (int a = 0; a < 3; ++a) {
            c.ray.origin[a] = lattice(a, k[a]);
        }
        const double sign = unit(rng) < 0.5 ? -1.0 : 1.0;
        const int axis = i % 3;
        switch (i % 4) {
            case 0:  // along a voxel edge
                c.ray.direction[axis] = sign;
                break;
            case 1:  // in a voxel face, at an angle
                c.ray.direction[axis] = sign;
                c.ray.direction[(axis + 1) % 3] = unit(rng) - 0.5;
                break;
            case 2:  // through voxel corners: one lattice step on every axis at a time
                for (int a = 0; a < 3; ++a) {
                    const int step = k[a] < divisions / 2 ? 1 : -1;
                    c.ray.direction[a] = lattice(a, k[a] + step) - lattice(a, k[a]);
                }
                break;
            default:  // from a lattice point, anywhere
                c.ray.direction = {unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5};
                break;
        }
        // Back the origin off along the ray half the time, so it starts outside the world.
        if (i % 8 >= 4) {
            c.ray.origin = c.ray.origin - c.ray.direction * 3.0;
        }
        rays.push_back(c);
    }
    return rays;
}

}  // namespace rt::test
