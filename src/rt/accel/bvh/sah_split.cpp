#include "rt/accel/bvh/sah_split.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <thread>
#include <vector>

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

// A bin holds what the two sides of a split need, so that neither side is read again to learn
// its boxes, its centres' box (the next split's bins) or its triangle count.
struct Bin {
    Box box;
    Box centroids;
    std::uint32_t triangles = 0;
    std::uint32_t count = 0;

    void grow(const Bin& b) {
        box.grow(b.box);
        centroids.grow(b.centroids);
        triangles += b.triangles;
        count += b.count;
    }
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
    int last = kBins - 1;
    int operator()(float c) const {
        const int b = static_cast<int>((c - lo) * scale);
        return std::clamp(b, 0, last);
    }
};

// A range of few references gets as many bins as references (at least two): more could only
// stay empty, and each bin costs the same to clear and sweep whatever it holds. Most calls are
// for such small ranges near the leaves.
int bin_count(std::uint32_t references) {
    return static_cast<int>(std::clamp<std::uint32_t>(references, 2, kBins));
}

Binner binner_for(const Box& cb, int axis, int bins) {
    const float extent = cb.hi[axis] - cb.lo[axis];
    return {cb.lo[axis], extent > 0.0f ? static_cast<float>(bins) * 0.9999f / extent : 0.0f,
            bins - 1};
}

using AxisBins = std::array<std::array<Bin, kBins>, 3>;

#if defined(__SSE2__)
// One pass over the references, each binned on all three axes: the three centroids and bin
// numbers in one register (the same float operations as Binner and PolygonReference::centroid,
// lane by lane, so the partition that follows puts each reference on the side its bin was counted
// on), the boxes grown as registers. Lane 3 of each register holds whatever follows the three
// floats loaded: unused.
void bin_references(std::span<const PolygonReference> refs, const ReferenceRange& r,
                    const std::array<Binner, 3>& binners, int count, AxisBins& bins) {
    struct Wide {
        __m128 lo = _mm_set1_ps(HUGE_VALF);
        __m128 hi = _mm_set1_ps(-HUGE_VALF);
        __m128 centroid_lo = _mm_set1_ps(HUGE_VALF);
        __m128 centroid_hi = _mm_set1_ps(-HUGE_VALF);
    };
    // Kept between calls so that only the bins in use are cleared.
    static thread_local std::array<std::array<Wide, kBins>, 3> boxes;
    for (auto& axis_boxes : boxes) {
        std::fill_n(axis_boxes.begin(), count, Wide{});
    }
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
            const int b = std::clamp(bin[axis], 0, count - 1);
            Wide& box = boxes[axis][b];
            box.lo = _mm_min_ps(lo, box.lo);
            box.hi = _mm_max_ps(hi, box.hi);
            box.centroid_lo = _mm_min_ps(centroid, box.centroid_lo);
            box.centroid_hi = _mm_max_ps(centroid, box.centroid_hi);
            bins[axis][b].triangles += ref.triangles;
            ++bins[axis][b].count;
        }
    }
    const auto store = [](__m128 lo_in, __m128 hi_in, Box& out) {
        alignas(16) float lo[4];
        alignas(16) float hi[4];
        _mm_store_ps(lo, lo_in);
        _mm_store_ps(hi, hi_in);
        for (int k = 0; k < 3; ++k) {
            out.lo[k] = lo[k];
            out.hi[k] = hi[k];
        }
    };
    for (int axis = 0; axis < 3; ++axis) {
        for (int b = 0; b < count; ++b) {
            const Wide& w = boxes[axis][b];
            store(w.lo, w.hi, bins[axis][b].box);
            store(w.centroid_lo, w.centroid_hi, bins[axis][b].centroids);
        }
    }
}
#else
void bin_references(std::span<const PolygonReference> refs, const ReferenceRange& r,
                    const std::array<Binner, 3>& binners, int count, AxisBins& bins) {
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
        const PolygonReference& ref = refs[i];
        Box centre;
        for (int k = 0; k < 3; ++k) {
            centre.lo[k] = centre.hi[k] = ref.centroid(k);
        }
        for (int axis = 0; axis < 3; ++axis) {
            Bin& bin = bins[axis][binners[axis](ref.centroid(axis))];
            bin.box.grow(ref.box);
            bin.centroids.grow(centre);
            bin.triangles += ref.triangles;
            ++bin.count;
        }
    }
}
#endif

// Ranges at least this big are binned by `threads` threads, each a run of the references into
// bins of its own, then summed: the same bins as one pass (min, max and counts do not depend on
// the order).
constexpr std::uint32_t kParallelBinning = 1u << 18;

void bin_in_parallel(std::span<const PolygonReference> refs, const ReferenceRange& r,
                     const std::array<Binner, 3>& binners, int count, unsigned threads,
                     AxisBins& bins) {
    if (threads <= 1 || r.size() < kParallelBinning) {
        bin_references(refs, r, binners, count, bins);
        return;
    }
    const auto at = [&](unsigned t) {
        return r.begin + static_cast<std::uint32_t>(std::uint64_t{r.size()} * t / threads);
    };
    std::vector<std::unique_ptr<AxisBins>> parts;
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) {
        parts.push_back(std::make_unique<AxisBins>());
        pool.emplace_back([&, t, part = parts.back().get()] {
            ReferenceRange run;
            run.begin = at(t);
            run.end = at(t + 1);
            bin_references(refs, run, binners, count, *part);
        });
    }
    ReferenceRange first;
    first.begin = r.begin;
    first.end = at(1);
    bin_references(refs, first, binners, count, bins);
    for (std::thread& t : pool) {
        t.join();
    }
    for (const auto& part : parts) {
        for (int axis = 0; axis < 3; ++axis) {
            for (int b = 0; b < count; ++b) {
                bins[axis][b].grow((*part)[axis][b]);
            }
        }
    }
}

// Bins every reference on the three axes in one pass over them (each axis whose centroids
// spread), then sweeps each axis's bins in turn, axis 0 first, for the cheapest split.
void evaluate_axes(std::span<const PolygonReference> refs, const ReferenceRange& r,
                   const std::array<Binner, 3>& binners, int count, unsigned threads,
                   AxisBins& bins, BestSplit& best) {
    const Box& cb = r.centroids;
    bin_in_parallel(refs, r, binners, count, threads, bins);
    for (int axis = 0; axis < 3; ++axis) {
        if (!(cb.hi[axis] > cb.lo[axis])) {
            continue;
        }
        const std::array<Bin, kBins>& axis_bins = bins[axis];
        std::array<double, kBins> right_cost{};
        Box right;
        std::uint32_t right_triangles = 0;
        for (int b = count - 1; b > 0; --b) {
            right.grow(axis_bins[b].box);
            right_triangles += axis_bins[b].triangles;
            right_cost[b] = right.half_area() * packets(right_triangles);
        }
        Box left;
        std::uint32_t left_triangles = 0;
        std::uint32_t left_count = 0;
        for (int b = 1; b < count; ++b) {
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

// The side made of bins [first, last) of one axis, starting at `begin` in the references.
ReferenceRange side_of(const std::array<Bin, kBins>& bins, int first, int last,
                       std::uint32_t begin) {
    Bin sum;
    for (int b = first; b < last; ++b) {
        sum.grow(bins[b]);
    }
    ReferenceRange side;
    side.begin = begin;
    side.end = begin + sum.count;
    side.box = sum.box;
    side.centroids = sum.centroids;
    side.triangles = sum.triangles;
    return side;
}

SplitDecision split_at(std::span<PolygonReference> refs, const ReferenceRange& r,
                       std::uint32_t middle) {
    return {false, make_range(refs, r.begin, middle), make_range(refs, middle, r.end)};
}

SplitDecision median_split(std::span<PolygonReference> refs, const ReferenceRange& r) {
    const Box& cb = r.centroids;
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
        for (int k = 0; k < 3; ++k) {
            const float c = refs[i].centroid(k);
            r.centroids.lo[k] = std::min(r.centroids.lo[k], c);
            r.centroids.hi[k] = std::max(r.centroids.hi[k], c);
        }
        r.triangles += refs[i].triangles;
    }
    return r;
}

SplitDecision split_range(std::span<PolygonReference> refs, const ReferenceRange& range,
                          bool by_median, unsigned threads) {
    if (range.size() <= 1 || (range.triangles <= 4 && !by_median)) {
        return {};
    }
    if (by_median) {
        return median_split(refs, range);
    }
    const int count = bin_count(range.size());
    std::array<Binner, 3> binners;
    for (int axis = 0; axis < 3; ++axis) {
        binners[axis] = binner_for(range.centroids, axis, count);
    }
    // Kept between calls so that only the bins in use are cleared.
    static thread_local AxisBins bins;
    for (auto& axis_bins : bins) {
        std::fill_n(axis_bins.begin(), count, Bin{});
    }
    BestSplit best;
    evaluate_axes(refs, range, binners, count, threads, bins, best);
    const double area = range.box.half_area();
    const double leaf_cost = area * packets(range.triangles);
    if (range.triangles <= kMaxLeafTriangles && leaf_cost <= best.cost + kTraversalCost * area) {
        return {};
    }
    if (best.axis < 0) {  // every centroid the same: any halving is as good
        return median_split(refs, range);
    }
    const Binner& binner = binners[best.axis];
    std::partition(
        refs.begin() + range.begin, refs.begin() + range.end,
        [&](const PolygonReference& r) { return binner(r.centroid(best.axis)) < best.bin; });
    const std::array<Bin, kBins>& axis_bins = bins[best.axis];
    SplitDecision split;
    split.leaf = false;
    split.left = side_of(axis_bins, 0, best.bin, range.begin);
    split.right = side_of(axis_bins, best.bin, count, split.left.end);
    return split;
}

}  // namespace rt::bvh
