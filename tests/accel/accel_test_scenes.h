// Scenes and rays for the exit-culling and z-buffer tests: random soups (triangles, warped quads,
// concave many-cornered polygons), spheres, boxes and the manual's twocubes.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/core/ray.h"
#include "rt/scene/read/load_scene.h"
#include "rt/scene/scene.h"

#include "support/scene_builder.h"
#include "support/temp_dir.h"

namespace rt::test {

inline Vec3 random_point(std::mt19937_64& rng, const Vec3& lo, const Vec3& hi) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {lo.x + (hi.x - lo.x) * u(rng), lo.y + (hi.y - lo.y) * u(rng),
            lo.z + (hi.z - lo.z) * u(rng)};
}

inline Vec3 random_direction(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    Vec3 d;
    do {
        d = {n(rng), n(rng), n(rng)};
    } while (length(d) < 1e-6);
    return normalize(d);
}

/// Random polygons in [-10, 10]^3: triangles of many sizes, quads (with one corner lifted off the
/// plane if `warped`) and concave stars in random planes.
inline Scene make_soup(std::uint64_t seed, int count, bool warped = false) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    SceneBuilder b;
    for (int i = 0; i < count; ++i) {
        const Vec3 centre = random_point(rng, {-10, -10, -10}, {10, 10, 10});
        const double size = std::pow(10.0, -1.5 + 2.0 * u(rng));
        const Vec3 e1 = random_direction(rng) * size;
        Vec3 e2 = cross(random_direction(rng), e1);
        e2 = normalize(e2) * size;
        const int kind = i % 5;
        if (kind < 3) {
            b.add_polygon({centre, centre + e1, centre + e2 * u(rng) + e1 * u(rng)});
        } else if (kind == 3) {
            const Vec3 lift = normalize(cross(e1, e2)) * size * (warped ? 0.2 * u(rng) : 0.0);
            b.add_polygon({centre, centre + e1, centre + e1 + e2 + lift, centre + e2});
        } else {
            std::vector<Vec3> star;
            for (int k = 0; k < 10; ++k) {
                const double a = 2.0 * 3.141592653589793 * k / 10.0;
                const double r = (k % 2 == 0) ? 1.0 : 0.4;
                star.push_back(centre + e1 * (r * std::cos(a)) + e2 * (r * std::sin(a)));
            }
            b.add_polygon(star);
        }
    }
    return b.scene();
}

/// Adds the closed axis-aligned box [lo, hi]: six quads with outward normals, sharing corners.
inline void add_box(SceneBuilder& b, const Vec3& lo, const Vec3& hi) {
    auto quad = [&](Vec3 a, Vec3 c, Vec3 d, Vec3 e, Vec3 out) { b.add_polygon({a, c, d, e}, out); };
    const double x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
    quad({x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}, {x0, y0, z1}, {-1, 0, 0});
    quad({x1, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x1, y1, z0}, {1, 0, 0});
    quad({x0, y0, z0}, {x0, y0, z1}, {x1, y0, z1}, {x1, y0, z0}, {0, -1, 0});
    quad({x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1}, {0, 1, 0});
    quad({x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0}, {0, 0, -1});
    quad({x0, y0, z1}, {x0, y1, z1}, {x1, y1, z1}, {x1, y0, z1}, {0, 0, 1});
}

/// Axis-aligned boxes scattered on a floor: closed quads sharing corners.
inline Scene make_boxes(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    SceneBuilder b;
    b.add_polygon({{-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20}}, {0, 1, 0});
    for (int i = 0; i < count; ++i) {
        const Vec3 lo = random_point(rng, {-15, 0, -15}, {13, 2, 13});
        add_box(b, lo, lo + random_point(rng, {0.5, 0.5, 0.5}, {3, 6, 3}));
    }
    return b.scene();
}

/// The manual's scene, read from the source tree.
inline Scene load_twocubes() {
    Diagnostics diagnostics;
    return load_scene(source_dir() / "tests/data/scene/manual/twocubes.scn", ReaderDialect{},
                      diagnostics);
}

/// A point on polygon `id`: the mean of its corners nudged towards a random corner.
inline Vec3 point_on(const Scene& scene, std::uint32_t id, std::mt19937_64& rng) {
    const Polygon& p = scene.polygons[id];
    Vec3 mean;
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        mean += scene.corner_position(p, k);
    }
    mean = mean / p.corner_count;
    std::uniform_int_distribution<std::uint32_t> pick(0, p.corner_count - 1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return mean + (scene.corner_position(p, pick(rng)) - mean) * u(rng);
}

struct TestRay {
    Ray ray;
    Interval t;
};

/// Rays of every kind exit culling meets: origins inside the world box, outside it (up to a few
/// diagonals away), on polygons (like reflected rays and shadow feelers), in a polygon's plane
/// looking along it; directions random, along an axis or towards a polygon; t.max unbounded or
/// finite.
inline std::vector<TestRay> make_test_rays(const Scene& scene, std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto [lo, hi] = scene.bounds();
    const Vec3 centre = (lo + hi) * 0.5;
    const double diagonal = length(hi - lo);
    std::vector<TestRay> rays;
    rays.reserve(count);
    std::uniform_int_distribution<std::uint32_t> polygon(
        0, static_cast<std::uint32_t>(scene.polygons.size() - 1));
    for (int i = 0; i < count; ++i) {
        TestRay r;
        const int origin_kind = i % 4;
        if (origin_kind == 0) {
            r.ray.origin = random_point(rng, lo, hi);
        } else if (origin_kind == 1) {
            r.ray.origin = centre + random_direction(rng) * diagonal * (0.6 + 3.0 * u(rng));
        } else if (origin_kind == 2) {
            r.ray.origin = point_on(scene, polygon(rng), rng);
        } else {
            // In the plane of a polygon, beside it, looking along the plane: the grazing case,
            // whose reported t comes from the corners, not the plane.
            const std::uint32_t id = polygon(rng);
            const Vec3 n = scene.polygons[id].normal;
            const Vec3 along = cross(n, random_direction(rng));
            const Vec3 in_plane = length(along) > 1e-3 ? normalize(along) : Vec3{};
            r.ray.origin = point_on(scene, id, rng) + in_plane * (diagonal * 0.05 * u(rng));
            if (i % 3 != 0) {
                r.ray.direction = u(rng) < 0.5 ? in_plane : -in_plane;
                r.t.min = 1e-9;
                rays.push_back(r);
                continue;
            }
        }
        const int direction_kind = (i / 4) % 4;
        if (direction_kind == 0) {
            Vec3 axis;
            axis[static_cast<int>(u(rng) * 3.0) % 3] = u(rng) < 0.5 ? -1.0 : 1.0;
            r.ray.direction = axis;
        } else if (direction_kind == 1) {
            const Vec3 target = point_on(scene, polygon(rng), rng);
            r.ray.direction =
                target == r.ray.origin ? random_direction(rng) : target - r.ray.origin;
        } else {
            r.ray.direction = random_direction(rng) * (0.5 + u(rng));
        }
        r.t.min = origin_kind >= 2 ? 1e-9 : 0.0;
        if ((i / 16) % 2 == 1) {
            r.t.max = diagonal * 2.0 * u(rng);
        }
        rays.push_back(r);
    }
    return rays;
}

}  // namespace rt::test
