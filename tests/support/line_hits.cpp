#include "support/line_hits.h"

#include <cmath>
#include <cstdio>
#include <iterator>

#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt::test {

namespace {

constexpr Interval kWholeLine{-kBeyondAnyScene, kBeyondAnyScene};

}  // namespace

LineHits hits_along(const Scene& scene, const Ray& ray) {
    const RaySpace space(ray);
    LineHits result;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const std::optional<double> t =
            intersect_polygon(space, scene.polygon_view(id), kWholeLine);
        const int winding = winding_number(space, scene.polygon_view(id));
        EXPECT_EQ(t.has_value(), winding != 0) << "hit and winding disagree on polygon " << id;
        if (t) {
            ++result.count;
            result.signed_winding += winding;
            result.polygons.push_back(id);
            result.depths.push_back(*t);
        }
    }
    return result;
}

std::string describe(const Ray& ray) {
    char text[200];
    std::snprintf(text, sizeof text, "ray from (%.17g, %.17g, %.17g) along (%.17g, %.17g, %.17g)",
                  ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                  ray.direction.z);
    return text;
}

void expect_even_crossing(const Scene& scene, const Ray& ray) {
    const LineHits h = hits_along(scene, ray);
    ASSERT_TRUE(h.count == 0 || h.count == 2) << h.count << " hits, " << describe(ray);
    EXPECT_EQ(h.signed_winding, 0) << describe(ray);
    // Two hits at one depth (the line clipping an edge or corner, each face's plane giving its
    // own rounding of that depth) have no order to check.
    if (h.count == 2 &&
        std::fabs(h.depths[0] - h.depths[1]) > 1e-9 * (1.0 + std::fabs(h.depths[0]))) {
        const bool first_is_nearer = h.depths[0] <= h.depths[1];
        const Vec3& near_normal = scene.polygons[h.polygons[first_is_nearer ? 0 : 1]].normal;
        const Vec3& far_normal = scene.polygons[h.polygons[first_is_nearer ? 1 : 0]].normal;
        const double grazing = 1e-6 * length(ray.direction);
        const double entering = dot(near_normal, ray.direction);
        const double leaving = dot(far_normal, ray.direction);
        if (std::fabs(entering) > grazing && std::fabs(leaving) > grazing) {
            EXPECT_LT(entering, 0.0) << describe(ray);
            EXPECT_GT(leaving, 0.0) << describe(ray);
        }
    }
}

void expect_two_crossings(const Scene& scene, const Ray& ray) {
    EXPECT_EQ(hits_along(scene, ray).count, 2) << describe(ray);
    expect_even_crossing(scene, ray);
}

void expect_consistent_loops(const Scene& scene) {
    for (const Polygon& p : scene.polygons) {
        std::vector<Vec3> loop;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            loop.push_back(scene.corner_position(p, k));
        }
        ASSERT_GT(dot(newell_normal(loop), p.normal), 0.0);
    }
}

Vec3 random_unit(std::mt19937_64& random) {
    std::normal_distribution<double> gauss;
    const Vec3 v{gauss(random), gauss(random), gauss(random)};
    return normalize(v);
}

Ray ray_through(const Vec3& through, const Vec3& direction) {
    return {through - direction * 8.0, direction};
}

std::vector<Vec3> dyadic_directions() {
    constexpr double kParts[] = {-1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0};
    std::vector<Vec3> out;
    out.reserve(std::size(kParts) * std::size(kParts) * std::size(kParts));
    for (const double a : kParts) {
        for (const double b : kParts) {
            for (const double c : kParts) {
                if (a != 0.0 || b != 0.0 || c != 0.0) {
                    out.push_back({a, b, c});
                }
            }
        }
    }
    return out;
}

std::vector<Vec3> box_corners(const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> out;
    out.reserve(8);
    for (int i = 0; i < 8; ++i) {
        out.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    }
    return out;
}

}  // namespace rt::test
