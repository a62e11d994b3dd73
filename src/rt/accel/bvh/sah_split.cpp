#include "rt/accel/bvh/sah_split.h"

#include <algorithm>
#include <array>
#include <limits>

namespace rt::bvh {

namespace {

constexpr int kBins = 32;
// Cost of testing one node relative to one packet of four triangles.
constexpr double kTraversalCost = 2.0;

double packets(std::uint32_t triangles) {
    return static_cast<double>((triangles + 3) / 4);
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

// Bins every reference on the three axes in one pass over them (each axis whose centroids
// spread), then sweeps each axis's bins in turn, axis 0 first, for the cheapest split.
void evaluate_axes(std::span<const PolygonReference> refs, const ReferenceRange& r,
                   const CentroidBounds& cb, BestSplit& best) {
    std::array<std::array<Bin, kBins>, 3> bins{};
    std::array<Binner, 3> binners;
    std::array<bool, 3> spread{};
    for (int axis = 0; axis < 3; ++axis) {
        spread[axis] = cb.hi[axis] > cb.lo[axis];
        binners[axis] = binner_for(cb, axis);
    }
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
        const PolygonReference& ref = refs[i];
        for (int axis = 0; axis < 3; ++axis) {
            Bin& bin = bins[axis][binners[axis](ref.centroid(axis))];
            bin.box.grow(ref.box);
            bin.triangles += ref.triangles;
            ++bin.count;
        }
    }
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
