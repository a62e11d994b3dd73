#include "rt/accel/bvh/polygon_references.h"

#include <algorithm>
#include <cmath>
#include <thread>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/accel/parallel_parts.h"
#include "rt/core/huge_pages.h"

namespace rt::bvh {

namespace {

// ray_polygon.cpp takes the plane's t only where |cos(normal, direction)| > 1e-6; a point off the
// plane by h then moves the plane hit by at most h / 1e-6 along the ray. 2^21 > 2e6 spares a
// factor of two.
constexpr double kPlaneDeviationGain = 0x1p21;

// Runs of polygons a build thread takes, on average (make_polygon_references).
constexpr std::uint32_t kRunsPerThread = 8;

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

#if defined(__AVX2__)
// A triangle's box as polygon_box, widened and rounded to float as append_references does, with
// the three axes in the lanes of one register (lane 3 zero): the same double and float operations
// in the same order on each axis, so the same bits. minpd and maxpd are min_components and
// max_components exactly (a < b ? a : b), and the deviation's and the sizes' maxima take
// non-negative finite values, where order does not matter. Most scenes are triangles: done
// one polygon at a time, the scalar code took about 60 ns each. False if the triangle cannot be
// boxed; `size` is then undefined.
bool triangle_reference(const Vec3* positions, const std::uint32_t* corners, const Polygon& p,
                        PolygonReference& r, double& size) {
    const __m256i xyz = _mm256_setr_epi64x(-1, -1, -1, 0);
    const __m256d a = _mm256_maskload_pd(&positions[corners[0]].x, xyz);
    const __m256d b = _mm256_maskload_pd(&positions[corners[1]].x, xyz);
    const __m256d c = _mm256_maskload_pd(&positions[corners[2]].x, xyz);
    const __m256d n = _mm256_maskload_pd(&p.normal.x, xyz);
    const __m256d zero = _mm256_setzero_pd();
    // x - x is 0 for a finite x and NaN otherwise.
    const auto all_finite = [zero](__m256d u, __m256d v) {
        const __m256d sum = _mm256_add_pd(_mm256_sub_pd(u, u), _mm256_sub_pd(v, v));
        return _mm256_movemask_pd(_mm256_cmp_pd(sum, zero, _CMP_EQ_OQ)) == 0xf;
    };
    if (!all_finite(a, b) || !all_finite(c, n)) {
        return false;
    }
    __m256d lo = _mm256_min_pd(_mm256_min_pd(a, b), c);
    __m256d hi = _mm256_max_pd(_mm256_max_pd(a, b), c);
    // dot(normal, b - a) and dot(normal, c - a), each (x + y) + z: hadd pairs x + y of each in the
    // low lanes and z + 0 in the high ones (a -0 z may become +0; fabs makes them equal).
    const __m256d pairs = _mm256_hadd_pd(_mm256_mul_pd(n, _mm256_sub_pd(b, a)),
                                         _mm256_mul_pd(n, _mm256_sub_pd(c, a)));
    const __m128d dots = _mm_add_pd(_mm256_castpd256_pd128(pairs), _mm256_extractf128_pd(pairs, 1));
    const __m128d sign = _mm_set1_pd(-0.0);
    const __m128d deviations = _mm_andnot_pd(sign, dots);
    const double deviation =
        std::max(_mm_cvtsd_f64(deviations), _mm_cvtsd_f64(_mm_unpackhi_pd(deviations, deviations)));
    const __m256d sign4 = _mm256_set1_pd(-0.0);
    const __m256d largest =
        _mm256_max_pd(_mm256_max_pd(_mm256_andnot_pd(sign4, a), _mm256_andnot_pd(sign4, b)),
                      _mm256_andnot_pd(sign4, c));
    const auto widest_lane = [](__m256d v) {
        const __m128d low = _mm256_castpd256_pd128(v);
        const double xy = std::max(_mm_cvtsd_f64(low), _mm_cvtsd_f64(_mm_unpackhi_pd(low, low)));
        return std::max(xy, _mm_cvtsd_f64(_mm256_extractf128_pd(v, 1)));
    };
    const double corner_size = widest_lane(largest);
    const __m256d widen = _mm256_set1_pd((deviation + 0x1p-48 * corner_size) * kPlaneDeviationGain);
    lo = _mm256_sub_pd(lo, widen);
    hi = _mm256_add_pd(hi, widen);
    if (!all_finite(lo, hi)) {
        return false;
    }
    // float_below and float_above, lane by lane: blendv chooses by the sign bit, which the
    // comparison's all-ones lanes keep through the conversion to float.
    const __m128i one = _mm_set1_epi32(1);
    const __m128 lo_nearest = _mm256_cvtpd_ps(lo);
    const __m128i lo_bits = _mm_castps_si128(lo_nearest);
    const __m128i lo_stepped =
        _mm_sub_epi32(_mm_add_epi32(lo_bits, _mm_slli_epi32(_mm_srli_epi32(lo_bits, 31), 1)), one);
    const __m128 lo_float =
        _mm_blendv_ps(lo_nearest, _mm_castsi128_ps(lo_stepped),
                      _mm256_cvtpd_ps(_mm256_cmp_pd(_mm256_cvtps_pd(lo_nearest), lo, _CMP_GT_OQ)));
    const __m128 hi_nearest = _mm256_cvtpd_ps(hi);
    const __m128i hi_bits = _mm_castps_si128(hi_nearest);
    const __m128i hi_stepped =
        _mm_sub_epi32(_mm_add_epi32(hi_bits, one), _mm_slli_epi32(_mm_srli_epi32(hi_bits, 31), 1));
    const __m128 hi_float =
        _mm_blendv_ps(hi_nearest, _mm_castsi128_ps(hi_stepped),
                      _mm256_cvtpd_ps(_mm256_cmp_pd(_mm256_cvtps_pd(hi_nearest), hi, _CMP_LT_OQ)));
    alignas(16) float lo_out[4];
    alignas(16) float hi_out[4];
    _mm_store_ps(lo_out, lo_float);
    _mm_store_ps(hi_out, hi_float);
    for (int k = 0; k < 3; ++k) {
        r.box.lo[k] = lo_out[k];
        r.box.hi[k] = hi_out[k];
    }
    size = widest_lane(_mm256_max_pd(_mm256_andnot_pd(sign4, _mm256_cvtps_pd(lo_float)),
                                     _mm256_andnot_pd(sign4, _mm256_cvtps_pd(hi_float))));
    return true;
}
#endif

// One run's share: its references were written from the run's first polygon's place on.
struct Run {
    std::size_t bounded = 0;
    std::vector<std::uint32_t> unbounded;
    double scale = 0.0;
};

// Writes the references of polygons [first, last), in order, from `out` on.
void write_references(const Scene& scene, std::uint32_t first, std::uint32_t last,
                      PolygonReference* out, Run& run) {
    const Vec3* positions = scene.positions.data();
    const std::uint32_t* corners = scene.corners.data();
    for (std::uint32_t id = first; id < last; ++id) {
        const Polygon& p = scene.polygons[id];
        if (p.corner_count < 3) {
            continue;
        }
        PolygonReference r;
        double size = 0.0;
#if defined(__AVX2__)
        if (p.corner_count == 3) {
            if (!triangle_reference(positions, corners + p.first_corner, p, r, size)) {
                run.unbounded.push_back(id);
                continue;
            }
        } else
#endif
        {
            Vec3 lo;
            Vec3 hi;
            if (!polygon_box(positions, corners + p.first_corner, p, lo, hi)) {
                run.unbounded.push_back(id);
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                r.box.lo[k] = float_below(lo[k]);
                r.box.hi[k] = float_above(hi[k]);
                size = std::max(size, std::max(std::fabs(static_cast<double>(r.box.lo[k])),
                                               std::fabs(static_cast<double>(r.box.hi[k]))));
            }
        }
        if (!std::isfinite(size)) {  // beyond float's range: keep the answer right, if slow
            run.unbounded.push_back(id);
            continue;
        }
        run.scale = std::max(run.scale, size);
        r.polygon = id;
        r.triangles = p.corner_count - 2;
        out[run.bounded++] = r;
    }
}

}  // namespace

PolygonReferences make_polygon_references(const Scene& scene, unsigned threads) {
    if (threads == 0) {
        threads = std::max(1u, std::thread::hardware_concurrency());
    }
    const auto polygons = static_cast<std::uint32_t>(scene.polygons.size());
    // Runs of at least 16k polygons, several a thread, each thread taking the next when done with
    // its last (so a core slowed by another program holds no other back); the runs are joined in
    // polygon order, so the result does not depend on the thread count.
    const std::uint32_t runs = std::clamp<std::uint32_t>(
        threads * kRunsPerThread, 1, std::max<std::uint32_t>(polygons >> 14, 1));
    const auto bound = [&](std::uint32_t r) {
        return static_cast<std::uint32_t>(std::uint64_t{polygons} * r / runs);
    };
    // Sized without being written (ReferenceArray): each run writes its own part, faulting in its
    // own fresh memory, from its first polygon's place. Before, the others' references were
    // written elsewhere and copied in after.
    PolygonReferences refs;
    reserve_huge(refs.bounded, polygons);
    refs.bounded.resize(polygons);
    std::vector<Run> parts(runs);
    share_out(runs, static_cast<int>(threads), [&](std::size_t r, int) {
        const auto run = static_cast<std::uint32_t>(r);
        write_references(scene, bound(run), bound(run + 1), refs.bounded.data() + bound(run),
                         parts[r]);
    });
    // A run that skipped polygons (fewer than three corners, or unbounded) left a gap before the
    // next run's part: close it.
    std::size_t end = 0;
    for (std::uint32_t r = 0; r < runs; ++r) {
        if (end != bound(r)) {
            std::copy_n(refs.bounded.begin() + bound(r), parts[r].bounded,
                        refs.bounded.begin() + static_cast<std::ptrdiff_t>(end));
        }
        end += parts[r].bounded;
        refs.unbounded.insert(refs.unbounded.end(), parts[r].unbounded.begin(),
                              parts[r].unbounded.end());
        refs.scale = std::max(refs.scale, parts[r].scale);
    }
    refs.bounded.resize(end);
    return refs;
}

}  // namespace rt::bvh
