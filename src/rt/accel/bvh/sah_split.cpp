#include "rt/accel/bvh/sah_split.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rt::bvh {

namespace {

constexpr int kBins = 32;
// Cost of testing one node relative to one packet of four triangles.
constexpr double kTraversalCost = 2.0;

// Whole packets: the integer division rounds up on purpose.
double packets(std::uint32_t triangles) {
    const std::uint32_t whole = (triangles + 3) / 4;
    return static_cast<double>(whole);
}

struct CentroidBounds {
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF};
    float hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
};

CentroidBounds centroid_bounds(std::span<const PolygonReference> refs, const ReferenceRange& r) {
    CentroidBounds b;
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
        for (int k = 0; k < 3; ++k) {
            const float c = refs[i].centroid(k);
            b.lo[k] = std::min(b.lo[k], c);
            b.hi[k] = std::max(b.hi[k], c);
        }
    }
    return b;
}

struct Bin {
    Box box;
    std::uint32_t triangles = 0;
    std::uint32_t count = 0;
};

struct BestSplit {
    double cost = std::numeric_limits<double>::infinity();
    int axis = -1;
    int bin = 0;  ///< references in bins < bin go left
};

// Maps a centroid to its bin on one axis.
struct Binner {
    float lo = 0.0f;
    float scale = 0.0f;
    int operator()(float c) const {
        const int b = static_cast<int>((c - lo) * scale);
        return std::clamp(b, 0, kBins - 1);
    }
};

Binner binner_for(const CentroidBounds& cb, int axis) {
    const float extent = cb.hi[axis] - cb.lo[axis];
    return {cb.lo[axis], extent > 0.0f ? kBins * 0.9999f / extent : 0.0f};
}

using AxisBins = std::array<std::array<Bin, kBins>, 3>;

#if defined(__SSE2__)
// One pass over the references, each binned on all three axes: the three centroids and bin
// numbers in one register (the same float operations as Binner, lane by lane, so the partition
// that follows puts each reference on the side its bin was counted on), the boxes grown as
// registers. Lane 3 of each register holds whatever follows the three floats loaded: unused.
void bin_references(std::span<const PolygonReference> refs, const ReferenceRange& r,
                    const std::array<Binner, 3>& binners, AxisBins& bins) {
    struct Wide {
        __m128 lo = _mm_set1_ps(HUGE_VALF);
        __m128 hi = _mm_set1_ps(-HUGE_VALF);
    };
    std::array<std::array<Wide, kBins>, 3> boxes;
    const __m128 origin = _mm_setr_ps(binners[0].lo, binners[1].lo, binners[2].lo, 0.0f);
    const __m128 scale = _mm_setr_ps(binners[0].scale, binners[1].scale, binners[2].scale, 0.0f);
    const __m128 half = _mm_set1_ps(0.5f);
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
        const PolygonReference& ref = refs[i];
        static_assert(offsetof(PolygonReference, box) == 0 && offsetof(Box, hi) == 12 &&
                          sizeof(PolygonReference) >= 28,
                      "four floats from lo and from hi stay inside the reference");
        const __m128 lo = _mm_loadu_ps(ref.box.lo);
        const __m128 hi = _mm_loadu_ps(ref.box.hi);
        const __m128 centroid = _mm_mul_ps(half, _mm_add_ps(lo, hi));
        alignas(16) std::int32_t bin[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(bin),
                        _mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(centroid, origin), scale)));
        for (int axis = 0; axis < 3; ++axis) {
            const int b = std::clamp(bin[axis], 0, kBins - 1);
            Wide& box = boxes[axis][b];
            box.lo = _mm_min_ps(lo, box.lo);
            box.hi = _mm_max_ps(hi, box.hi);
            bins[axis][b].triangles += ref.triangles;
            ++bins[axis][b].count;
        }
    }
    for (int axis = 0; axis < 3; ++axis) {
        for (int b = 0; b < kBins; ++b) {
            alignas(16) float lo[4];
            alignas(16) float hi[4];
            _mm_store_ps(lo, boxes[axis][b].lo);
            _mm_store_ps(hi, boxes[axis][b].hi);
            for (int k = 0; k < 3; ++k) {
                bins[axis][b].box.lo[k] = lo[k];
                bins[axis][b].box.hi[k] = hi[k];
            }
        }
    }
}
#else
void bin_references(std::span<const PolygonReference> refs, const ReferenceRange& r,
                    const std::array<Binner, 3>& binners, AxisBins& bins) {
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
        const PolygonReference& ref = refs[i];
        for (int axis = 0; axis < 3; ++axis) {
            Bin& bin = bins[axis][binners[axis](ref.centroid(axis))];
            bin.box.grow(ref.box);
            bin.triangles += ref.triangles;
            ++bin.count;
        }
    }
}
#endif

// Bins every reference on the three axes in one pass over them (each axis whose centroids
// spread), then sweeps each axis's bins in turn, axis 0 first, for the cheapest split.
void evaluate_axes(std::span<const PolygonReference> refs, const ReferenceRange& r,
                   const CentroidBounds& cb, BestSplit& best) {
    AxisBins bins{};
    std::array<Binner, 3> binners;
    std::array<bool, 3> spread{};
    for (int axis = 0; axis < 3; ++axis) {
        spread[axis] = cb.hi[axis] > cb.lo[axis];
        binners[axis] = binner_for(cb, axis);
    }
    bin_references(refs, r, binners, bins);
    for (int axis = 0; axis < 3; ++axis) {
        if (!spread[axis]) {
            continue;
        }
        const std::array<Bin, kBins>& axis_bins = bins[axis];
        std::array<double, kBins> right_cost{};
        Box right;
        std::uint32_t right_triangles = 0;
        for (int b = kBins - 1; b > 0; --b) {
            right.grow(axis_bins[b].box);
            right_triangles += axis_bins[b].triangles;
            right_cost[b] = right.half_area() * packets(right_triangles);
        }
        Box left;
        std::uint32_t left_triangles = 0;
        std::uint32_t left_count = 0;
        for (int b = 1; b < kBins; ++b) {
            left.grow(axis_bins[b - 1].box);
            left_triangles += axis_bins[b - 1].triangles;
            left_count += axis_bins[b - 1].count;
            if (left_count == 0 || left_count == r.size()) {
                continue;
            }
            const double cost = left.half_area() * packets(left_triangles) + right_cost[b];
            if (cost < best.cost) {
                best = {cost, axis, b};
            }
        }
    }
}

SplitDecision split_at(std::span<PolygonReference> refs, const ReferenceRange& r,
                       std::uint32_t middle) {
    return {false, make_range(refs, r.begin, middle), make_range(refs, middle, r.end)};
}

SplitDecision median_split(std::span<PolygonReference> refs, const ReferenceRange& r,
                           const CentroidBounds& cb) {
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
        if (cb.hi[k] - cb.lo[k] > cb.hi[axis] - cb.lo[axis]) {
            axis = k;
        }
    }
    const std::uint32_t middle = r.begin + r.size() / 2;
    std::nth_element(refs.begin() + r.begin, refs.begin() + middle, refs.begin() + r.end,
                     [axis](const PolygonReference& a, const PolygonReference& b) {
                         return a.centroid(axis) < b.centroid(axis);
                     });
    return split_at(refs, r, middle);
}

}  // namespace

ReferenceRange make_range(std::span<const PolygonReference> refs, std::uint32_t begin,
                          std::uint32_t end) {
    ReferenceRange r;
    r.begin = begin;
    r.end = end;
    for (std::uint32_t i = begin; i < end; ++i) {
        r.box.grow(refs[i].box);
        r.triangles += refs[i].triangles;
    }
    return r;
}

SplitDecision split_range(std::span<PolygonReference> refs, const ReferenceRange& range,
                          bool by_median) {
    if (range.size() <= 1 || (range.triangles <= 4 && !by_median)) {
        return {};
    }
    const CentroidBounds cb = centroid_bounds(refs, range);
    if (by_median) {
        return median_split(refs, range, cb);
    }
    BestSplit best;
    evaluate_axes(refs, range, cb, best);
    const double area = range.box.half_area();
    const double leaf_cost = area * packets(range.triangles);
    if (range.triangles <= kMaxLeafTriangles && leaf_cost <= best.cost + kTraversalCost * area) {
        return {};
    }
    if (best.axis < 0) {  // every centroid the same: any halving is as good
        return median_split(refs, range, cb);
    }
    const Binner binner = binner_for(cb, best.axis);
    const auto middle = std::partition(
        refs.begin() + range.begin, refs.begin() + range.end,
        [&](const PolygonReference& r) { return binner(r.centroid(best.axis)) < best.bin; });
    return split_at(refs, range, static_cast<std::uint32_t>(middle - refs.begin()));
}

}  // namespace rt::bvh
