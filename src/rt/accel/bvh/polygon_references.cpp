#include "rt/accel/bvh/polygon_references.h"

#include <algorithm>
#include <cmath>

namespace rt::bvh {

namespace {

// ray_polygon.cpp takes the plane's t only where |cos(normal, direction)| > 1e-6; a point off the
// plane by h then moves the plane hit by at most h / 1e-6 along the ray. 2^21 > 2e6 spares a
// factor of two.
constexpr double kPlaneDeviationGain = 0x1p21;

float round_down(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -HUGE_VALF) : f;
}

float round_up(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, HUGE_VALF) : f;
}

// The polygon's double box, widened for non-planarity; false if anything is not finite.
bool polygon_box(const Scene& scene, const Polygon& p, Vec3& lo, Vec3& hi) {
    const Vec3 first = scene.corner_position(p, 0);
    lo = hi = first;
    double deviation = 0.0;
    double size = 0.0;
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        const Vec3 c = scene.corner_position(p, k);
        lo = min_components(lo, c);
        hi = max_components(hi, c);
        deviation = std::max(deviation, std::fabs(dot(p.normal, c - first)));
        size = std::max({size, std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
    }
    if (!is_finite(lo) || !is_finite(hi) || !is_finite(p.normal) || !std::isfinite(deviation)) {
        return false;
    }
    // The deviation computed in double is itself off by a few units of the coordinates' size.
    const double widen = (deviation + 0x1p-48 * size) * kPlaneDeviationGain;
    lo = lo - Vec3{widen, widen, widen};
    hi = hi + Vec3{widen, widen, widen};
    return is_finite(lo) && is_finite(hi);
}

}  // namespace

PolygonReferences make_polygon_references(const Scene& scene) {
    PolygonReferences refs;
    refs.bounded.reserve(scene.polygons.size());
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        if (p.corner_count < 3) {
            continue;
        }
        Vec3 lo;
        Vec3 hi;
        if (!polygon_box(scene, p, lo, hi)) {
            refs.unbounded.push_back(id);
            continue;
        }
        PolygonReference r;
        double size = 0.0;
        for (int k = 0; k < 3; ++k) {
            r.box.lo[k] = round_down(lo[k]);
            r.box.hi[k] = round_up(hi[k]);
            size = std::max({size, std::fabs(static_cast<double>(r.box.lo[k])),
                             std::fabs(static_cast<double>(r.box.hi[k]))});
        }
        if (!std::isfinite(size)) {  // beyond float's range: keep the answer right, if slow
            refs.unbounded.push_back(id);
            continue;
        }
        refs.scale = std::max(refs.scale, size);
        r.polygon = id;
        r.triangles = p.corner_count - 2;
        refs.bounded.push_back(r);
    }
    return refs;
}

}  // namespace rt::bvh
