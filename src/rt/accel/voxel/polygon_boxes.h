// A cheap first look before the exact ray-polygon test, for the polygons the float packet test
// (cell_packets.h) cannot judge: each polygon's bounding box, grown a
// little and stored as floats rounded outward (24 bytes a polygon, next to each other in memory),
// tested against the ray's line. A line that misses the grown box cannot have the polygon around
// it in the exact test (which needs the line to pass through the polygon's projection, up to
// rounding far below the growth), so the polygon is skipped without touching the scene's records.
// It only ever skips polygons the exact test would miss: the answers stay brute force's.
//
// Also here: the ray as the float tests want it (TriangleProbe), and their scene scale.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/accel/voxel/box.h"
#include "rt/core/ray.h"

namespace rt {

/// The ray's line, prepared once per ray for many box tests.
struct LineProbe {
    // Inline: made once a query, and out of line its call cost a fifth of it.
    explicit LineProbe(const Ray& ray) : origin(ray.origin) {
        for (int a = 0; a < 3; ++a) {
            parallel[a] = ray.direction[a] == 0.0;
            inverse[a] = parallel[a] ? 0.0 : 1.0 / ray.direction[a];
            any_parallel = any_parallel || parallel[a];
        }
    }
    Vec3 origin;
    Vec3 inverse;        ///< 1 / direction (0 where the direction is 0: see `parallel`)
    bool parallel[3]{};  ///< direction component exactly 0
    bool any_parallel = false;
};

/// The slab test of a line against a float box `b` (lo x y z, hi x y z), one axis at a time.
/// False only if the line certainly misses the box.
inline bool line_may_meet_box_plain(const LineProbe& line, const float* b) {
    double near = -HUGE_VAL;
    double far = HUGE_VAL;
    for (int a = 0; a < 3; ++a) {
        const double lo = b[a];
        const double hi = b[3 + a];
        if (line.parallel[a]) {
            if (line.origin[a] < lo || line.origin[a] > hi) {
                return false;
            }
            continue;
        }
        double t0 = (lo - line.origin[a]) * line.inverse[a];
        double t1 = (hi - line.origin[a]) * line.inverse[a];
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        near = near > t0 ? near : t0;
        far = far < t1 ? far : t1;
    }
    return near <= far;
}

#if defined(__SSE2__)
/// The same test for a line with no zero direction component, x and y side by side in one
/// register and z on its own: the same operations on the same values, so the same answer, except
/// that a NaN (which no box excludes) counts as meeting, never skipping more than the plain test.
inline bool line_may_meet_box_sse2(const LineProbe& line, const float* b) {
    const __m128d origin_xy = _mm_set_pd(line.origin.y, line.origin.x);
    const __m128d inverse_xy = _mm_set_pd(line.inverse.y, line.inverse.x);
    const __m128d lo_xy =
        _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(b))));
    const __m128d hi_xy =
        _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(b + 3))));
    const __m128d t0 = _mm_mul_pd(_mm_sub_pd(lo_xy, origin_xy), inverse_xy);
    const __m128d t1 = _mm_mul_pd(_mm_sub_pd(hi_xy, origin_xy), inverse_xy);
    const __m128d low = _mm_min_pd(t0, t1);
    const __m128d high = _mm_max_pd(t0, t1);
    const double z0 = (static_cast<double>(b[2]) - line.origin.z) * line.inverse.z;
    const double z1 = (static_cast<double>(b[5]) - line.origin.z) * line.inverse.z;
    const __m128d z_low = _mm_set_sd(z0 < z1 ? z0 : z1);
    const __m128d z_high = _mm_set_sd(z0 < z1 ? z1 : z0);
    const __m128d near = _mm_max_sd(_mm_max_sd(low, _mm_unpackhi_pd(low, low)), z_low);
    const __m128d far = _mm_min_sd(_mm_min_sd(high, _mm_unpackhi_pd(high, high)), z_high);
    return _mm_comigt_sd(near, far) == 0;
}
#endif

/// The fastest form of the test this machine has for this line.
inline bool line_may_meet_box(const LineProbe& line, const float* b) {
#if defined(__SSE2__)
    if (!line.any_parallel) {
        return line_may_meet_box_sse2(line, b);
    }
#endif
    return line_may_meet_box_plain(line, b);
}

/// The ray as the float triangle test wants it, prepared on first use: most rays meet few
/// triangle boxes, some none. Only its triangle values: the boxes take the LineProbe.
class TriangleProbe {
public:
    TriangleProbe(const Ray& ray, double scene_scale) : ray_(ray), scene_scale_(scene_scale) {}
    const FloatRay& get() {
        if (!float_ray_) {
            float_ray_.emplace(ray_, scene_scale_, FloatRay::TrianglesOnly{});
        }
        return *float_ray_;
    }

private:
    const Ray& ray_;
    double scene_scale_;
    std::optional<FloatRay> float_ray_;
};

class PolygonBoxes {
public:
    /// `growth`: how far each box is grown on every side (the world's 2^-24 serves well).
    PolygonBoxes(const Scene& scene, double growth);

    /// False only if the line certainly misses the polygon.
    bool line_may_meet(const LineProbe& line, std::uint32_t polygon) const {
        return line_may_meet_box(line, boxes_.data() + 6 * static_cast<std::size_t>(polygon));
    }

    /// The largest |coordinate| of any triangle's corner as a float: a FloatRay's scene scale.
    double scale() const { return scale_; }

    std::size_t memory_bytes() const { return boxes_.capacity() * sizeof(float); }

private:
    void measure_triangle(const Scene& scene, std::uint32_t id);

    std::vector<float> boxes_;  ///< per polygon: lo x y z, hi x y z
    double scale_ = 0.0;
};

}  // namespace rt
