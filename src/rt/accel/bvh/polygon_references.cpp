#include "rt/accel/bvh/polygon_references.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/core/huge_pages.h"

namespace rt::bvh {

namespace {

// ray_polygon.cpp takes the plane's t only where |cos(normal, direction)| > 1e-6; a point off the
// plane by h then moves the plane hit by at most h / 1e-6 along the ray. 2^21 > 2e6 spares a
// factor of two.
constexpr double kPlaneDeviationGain = 0x1p21;

// The polygon's double box, widened for non-planarity; false if anything is not finite. Every
// corner is asked: a NaN drops out of a minimum taken after it, so a NaN corner between finite
// ones left a finite box that did not hold the first corner.
bool polygon_box(const Vec3* positions, const std::uint32_t* corners, const Polygon& p, Vec3& lo,
                 Vec3& hi) {
    const Vec3 first = positions[corners[0]];
    lo = hi = first;
    bool finite = is_finite(first) && is_finite(p.normal);
    double deviation = 0.0;
    double size = std::max(std::max(std::fabs(first.x), std::fabs(first.y)), std::fabs(first.z));
    for (std::uint32_t k = 1; k < p.corner_count; ++k) {
        const Vec3 c = positions[corners[k]];
        finite = finite && is_finite(c);
        lo = min_components(lo, c);
        hi = max_components(hi, c);
        deviation = std::max(deviation, std::fabs(dot(p.normal, c - first)));
        size = std::max(size, std::max(std::max(std::fabs(c.x), std::fabs(c.y)), std::fabs(c.z)));
    }
    if (!finite || !std::isfinite(deviation)) {
        return false;
    }
    // The deviation computed in double is itself off by a few units of the coordinates' size.
    const double widen = (deviation + 0x1p-48 * size) * kPlaneDeviationGain;
    lo = lo - Vec3{widen, widen, widen};
    hi = hi + Vec3{widen, widen, widen};
    return is_finite(lo) && is_finite(hi);
}

// Appends the references of polygons [first, last) to `refs`, in order.
void append_references(const Scene& scene, std::uint32_t first, std::uint32_t last,
                       PolygonReferences& refs) {
    reserve_huge(refs.bounded, refs.bounded.size() + (last - first));
    const Vec3* positions = scene.positions.data();
    const std::uint32_t* corners = scene.corners.data();
    for (std::uint32_t id = first; id < last; ++id) {
        const Polygon& p = scene.polygons[id];
        if (p.corner_count < 3) {
            continue;
        }
        Vec3 lo;
        Vec3 hi;
        if (!polygon_box(positions, corners + p.first_corner, p, lo, hi)) {
            refs.unbounded.push_back(id);
            continue;
        }
        PolygonReference r;
        double size = 0.0;
        for (int k = 0; k < 3; ++k) {
            r.box.lo[k] = float_below(lo[k]);
            r.box.hi[k] = float_above(hi[k]);
            size = std::max(size, std::max(std::fabs(static_cast<double>(r.box.lo[k])),
                                           std::fabs(static_cast<double>(r.box.hi[k]))));
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
}

}  // namespace

PolygonReferences make_polygon_references(const Scene& scene, unsigned threads) {
    if (threads == 0) {
        threads = std::max(1u, std::thread::hardware_concurrency());
    }
    const auto polygons = static_cast<std::uint32_t>(scene.polygons.size());
    // Each thread takes a run of at least 16k polygons; the runs are joined in polygon order, so
    // the result does not depend on the thread count.
    const std::uint32_t runs =
        std::clamp<std::uint32_t>(threads, 1, std::max<std::uint32_t>(polygons >> 14, 1));
    const auto bound = [&](std::uint32_t r) {
        return static_cast<std::uint32_t>(std::uint64_t{polygons} * r / runs);
    };
    // The first run is written straight into the result, which has room for all: only the
    // others' references are copied.
    PolygonReferences refs;
    reserve_huge(refs.bounded, polygons);
    std::vector<PolygonReferences> parts(runs);
    std::vector<std::thread> pool;
    for (std::uint32_t r = 1; r < runs; ++r) {
        pool.emplace_back([&, r] { append_references(scene, bound(r), bound(r + 1), parts[r]); });
    }
    append_references(scene, 0, bound(1), refs);
    for (std::thread& t : pool) {
        t.join();
    }
    for (std::uint32_t r = 1; r < runs; ++r) {
        refs.bounded.insert(refs.bounded.end(), parts[r].bounded.begin(), parts[r].bounded.end());
        refs.unbounded.insert(refs.unbounded.end(), parts[r].unbounded.begin(),
                              parts[r].unbounded.end());
        refs.scale = std::max(refs.scale, parts[r].scale);
        parts[r] = {};
    }
    return refs;
}

}  // namespace rt::bvh
