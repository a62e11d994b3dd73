#include "rt/accel/bvh/sah_split.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "rt/accel/parallel_parts.h"

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

// A box as eight floats {lo.x, lo.y, lo.z, lo.z, -hi.x, -hi.y, -hi.z, -hi.z}: growing it is one
// minimum over the eight lanes (min(-a, -b) is -max(a, b) exactly), so a bin is one 32-byte
// register to load, grow and store. Empty: every lane +inf (hi = -inf).
struct alignas(32) FlatBox {
    float v[8] = {HUGE_VALF, HUGE_VALF, HUGE_VALF, HUGE_VALF,
                  HUGE_VALF, HUGE_VALF, HUGE_VALF, HUGE_VALF};

    void grow(const FlatBox& b) {
#if defined(__AVX__)
        _mm256_store_ps(v, _mm256_min_ps(_mm256_load_ps(b.v), _mm256_load_ps(v)));
#else
        for (int k = 0; k < 8; ++k) {
            v[k] = b.v[k] < v[k] ? b.v[k] : v[k];
        }
#endif
    }
    Box box() const {
        Box out;
        for (int k = 0; k < 3; ++k) {
            out.lo[k] = v[k];
            out.hi[k] = -v[4 + k];
        }
        return out;
    }
};

// A bin's reference count (low word) and fan triangle count (high word), so that one addition
// counts both. Neither word carries into the other: a range has fewer than 2^32 references and
// triangles.
using PackedCount = std::uint64_t;

PackedCount one_reference(std::uint32_t triangles) {
    return (PackedCount{triangles} << 32) | 1u;
}
std::uint32_t references_in(PackedCount c) {
    return static_cast<std::uint32_t>(c);
}
std::uint32_t triangles_in(PackedCount c) {
    return static_cast<std::uint32_t>(c >> 32);
}

// The bins of the three axes: what the two sides of a split need to know their boxes and counts
// without reading their references again. Their centres' boxes come from the partition.
struct AxisBins {
    std::array<std::array<FlatBox, kBins>, 3> box;
    std::array<std::array<PackedCount, kBins>, 3> count{};

    void clear(int bins) {
        for (int axis = 0; axis < 3; ++axis) {
            std::fill_n(box[axis].begin(), bins, FlatBox{});
            std::fill_n(count[axis].begin(), bins, PackedCount{0});
        }
    }
    void add(const AxisBins& other, int bins) {
        for (int axis = 0; axis < 3; ++axis) {
            for (int b = 0; b < bins; ++b) {
                box[axis][b].grow(other.box[axis][b]);
                count[axis][b] += other.count[axis][b];
            }
        }
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

// Ranges at least this big are binned into two sets of bins in turn (bin_references).
constexpr std::uint32_t kTwoBinSets = 256;

#if defined(__SSE2__)
// One pass over the references, each binned on all three axes: the three centroids and bin
// numbers in one register (the same float operations as Binner and PolygonReference::centroid,
// lane by lane, so the partition that follows puts each reference on the side its bin was counted
// on; lo - (-hi) is lo + hi exactly), each bin grown by one eight-lane minimum.
void bin_references(std::span<const PolygonReference> refs, const ReferenceRange& r,
                    const std::array<Binner, 3>& binners, int count, AxisBins& bins) {
    const __m128 origin = _mm_setr_ps(binners[0].lo, binners[1].lo, binners[2].lo, binners[2].lo);
    const __m128 scale =
        _mm_setr_ps(binners[0].scale, binners[1].scale, binners[2].scale, binners[2].scale);
    const __m128 half = _mm_set1_ps(0.5f);
    const __m128 sign = _mm_set1_ps(-0.0f);
    const auto bin_one = [&](const PolygonReference& ref, AxisBins& into_bins) {
        static_assert(offsetof(PolygonReference, box) == 0 && offsetof(Box, hi) == 12,
                      "lo and hi are the reference's first six floats");
        // {lo0, lo1, lo2, hi0} and {lo2, hi0, hi1, hi2}, each to three lanes and a copy.
        const __m128 low_part = _mm_loadu_ps(ref.box.lo);
        const __m128 high_part = _mm_loadu_ps(ref.box.lo + 2);
        const __m128 lo = _mm_shuffle_ps(low_part, low_part, _MM_SHUFFLE(2, 2, 1, 0));
        const __m128 neg_hi =
            _mm_xor_ps(_mm_shuffle_ps(high_part, high_part, _MM_SHUFFLE(3, 3, 2, 1)), sign);
        const __m128 centroid = _mm_mul_ps(half, _mm_sub_ps(lo, neg_hi));
        alignas(16) std::int32_t bin[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(bin),
                        _mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(centroid, origin), scale)));
        const PackedCount counted = one_reference(ref.triangles);
#if defined(__AVX__)
        const __m256 flat = _mm256_set_m128(neg_hi, lo);
        const auto grow = [&](int axis, int b) {
            float* into = into_bins.box[axis][b].v;
            _mm256_store_ps(into, _mm256_min_ps(flat, _mm256_load_ps(into)));
            into_bins.count[axis][b] += counted;
        };
#else
        const auto grow = [&](int axis, int b) {
            float* into = into_bins.box[axis][b].v;
            _mm_store_ps(into, _mm_min_ps(lo, _mm_load_ps(into)));
            _mm_store_ps(into + 4, _mm_min_ps(neg_hi, _mm_load_ps(into + 4)));
            into_bins.count[axis][b] += counted;
        };
#endif
        for (int axis = 0; axis < 3; ++axis) {
            grow(axis, std::clamp(bin[axis], 0, count - 1));
        }
    };
    // Neighbouring references often share bins: alternating two sets of bins lets one
    // reference's minimum start before the previous one's store has landed.
    if (r.size() < kTwoBinSets) {
        for (std::uint32_t i = r.begin; i < r.end; ++i) {
            bin_one(refs[i], bins);
        }
        return;
    }
    static thread_local AxisBins odd;
    odd.clear(count);
    std::uint32_t i = r.begin;
    for (; i + 1 < r.end; i += 2) {
        bin_one(refs[i], bins);
        bin_one(refs[i + 1], odd);
    }
    if (i < r.end) {
        bin_one(refs[i], bins);
    }
    bins.add(odd, count);
}
#else
void bin_references(std::span<const PolygonReference> refs, const ReferenceRange& r,
                    const std::array<Binner, 3>& binners, int /*count*/, AxisBins& bins) {
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
        const PolygonReference& ref = refs[i];
        FlatBox flat;
        for (int k = 0; k < 3; ++k) {
            flat.v[k] = ref.box.lo[k];
            flat.v[4 + k] = -ref.box.hi[k];
        }
        for (int axis = 0; axis < 3; ++axis) {
            const int b = binners[axis](ref.centroid(axis));
            bins.box[axis][b].grow(flat);
            bins.count[axis][b] += one_reference(ref.triangles);
        }
    }
}
#endif

// Ranges at least this big are binned by `threads` threads, each taking the next run of
// kBinningRun references into bins of its own when done with its last, then summed: the same bins
// as one pass (min, max and counts do not depend on the order). Runs rather than one half a thread:
// when another program slows one core, the other threads take more runs instead of waiting.
constexpr std::uint32_t kParallelBinning = 1u << 18;
constexpr std::uint32_t kBinningRun = 1u << 15;

void bin_in_parallel(std::span<const PolygonReference> refs, const ReferenceRange& r,
                     const std::array<Binner, 3>& binners, int count, unsigned threads,
                     AxisBins& bins) {
    if (threads <= 1 || r.size() < kParallelBinning) {
        bin_references(refs, r, binners, count, bins);
        return;
    }
    const std::uint32_t runs = (r.size() + kBinningRun - 1) / kBinningRun;
    // Thread 0 (the calling one) bins into `bins`, each other thread into its own.
    std::vector<std::unique_ptr<AxisBins>> parts;
    for (unsigned t = 1; t < threads; ++t) {
        parts.push_back(std::make_unique<AxisBins>());
        parts.back()->clear(count);
    }
    share_out(runs, static_cast<int>(threads), [&](std::size_t i, int thread) {
        ReferenceRange run;
        run.begin = r.begin + static_cast<std::uint32_t>(i) * kBinningRun;
        run.end = std::min(r.end, run.begin + kBinningRun);
        bin_references(refs, run, binners, count,
                       thread == 0 ? bins : *parts[static_cast<std::size_t>(thread - 1)]);
    });
    for (const auto& part : parts) {
        bins.add(*part, count);
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
        const std::array<FlatBox, kBins>& boxes = bins.box[axis];
        const std::array<PackedCount, kBins>& counts = bins.count[axis];
        // The bins that hold references, in order (written without a branch). Only a split
        // just after one of them is weighed: a split just after an empty bin cuts the references
        // as the split before that bin does, into sides with the same boxes and counts bit for
        // bit (an empty bin grows nothing), so its cost is the same, and the sweep keeps the
        // first of equal costs. Near the leaves a range has as many bins as references, and
        // about a third of them are empty.
        std::array<std::uint8_t, kBins> held;  // NOLINT(cppcoreguidelines-pro-type-member-init)
        int held_count = 0;
        for (int b = 0; b < count; ++b) {
            held[static_cast<std::size_t>(held_count)] = static_cast<std::uint8_t>(b);
            held_count += counts[b] != 0 ? 1 : 0;
        }
        // right_cost[j]: the side of held bins j and above. Only [1, held_count) is written.
        std::array<double, kBins> right_cost;  // NOLINT(cppcoreguidelines-pro-type-member-init)
        FlatBox right;
        std::uint32_t right_triangles = 0;
        for (int j = held_count - 1; j > 0; --j) {
            const int b = held[static_cast<std::size_t>(j)];
            right.grow(boxes[b]);
            right_triangles += triangles_in(counts[b]);
            right_cost[j] = right.box().half_area() * packets(right_triangles);
        }
        FlatBox left;
        PackedCount left_count = 0;
        for (int j = 1; j < held_count; ++j) {
            const int b = held[static_cast<std::size_t>(j - 1)];
            left.grow(boxes[b]);
            left_count += counts[b];
            const std::uint32_t references = references_in(left_count);
            if (references == 0 || references == r.size()) {
                continue;
            }
            const double cost =
                left.box().half_area() * packets(triangles_in(left_count)) + right_cost[j];
            if (cost < best.cost) {
                best = {cost, axis, b + 1};
            }
        }
    }
}

// The side made of bins [first, last) of one axis, starting at `begin` in the references; its
// centres' box is the partition's to fill.
ReferenceRange side_of(const AxisBins& bins, int axis, int first, int last, std::uint32_t begin) {
    FlatBox box;
    PackedCount count = 0;
    for (int b = first; b < last; ++b) {
        box.grow(bins.box[axis][b]);
        count += bins.count[axis][b];
    }
    ReferenceRange side;
    side.begin = begin;
    side.end = begin + references_in(count);
    side.box = box.box();
    side.triangles = triangles_in(count);
    return side;
}

void grow_by_centroid(Box& box, const PolygonReference& ref) {
    for (int k = 0; k < 3; ++k) {
        const float c = ref.centroid(k);
        box.lo[k] = std::min(box.lo[k], c);
        box.hi[k] = std::max(box.hi[k], c);
    }
}

#if defined(__SSE2__)
// The two sides' boxes of centres, grown in registers as references are judged. Each side grows
// by the centre or by a value that leaves it as it is (+inf for a minimum, -inf for a maximum),
// chosen without a branch, so that judging a block of references has no branch to mispredict.
// The lanes are grow_by_centroid's float operations: std::min(box, c) is (c < box ? c : box),
// which _mm_min_ps(c, box) is, and so for the maximum; the boxes are the same bit for bit.
class CentroidBoxes {
public:
    void grow(bool left, const PolygonReference& ref) {
        // {lo0, lo1, lo2, hi0} and {lo2, hi0, hi1, hi2}, each to three lanes and a copy.
        const __m128 low_part = _mm_loadu_ps(ref.box.lo);
        const __m128 high_part = _mm_loadu_ps(ref.box.lo + 2);
        const __m128 lo = _mm_shuffle_ps(low_part, low_part, _MM_SHUFFLE(2, 2, 1, 0));
        const __m128 hi = _mm_shuffle_ps(high_part, high_part, _MM_SHUFFLE(3, 3, 2, 1));
        const __m128 centre = _mm_mul_ps(_mm_set1_ps(0.5f), _mm_add_ps(lo, hi));
        const __m128 left_mask = _mm_castsi128_ps(_mm_set1_epi32(left ? -1 : 0));
        const auto pick = [&](__m128 if_left, __m128 if_right) {
            return _mm_or_ps(_mm_and_ps(left_mask, if_left), _mm_andnot_ps(left_mask, if_right));
        };
        const __m128 none_lo = _mm_set1_ps(HUGE_VALF);
        const __m128 none_hi = _mm_set1_ps(-HUGE_VALF);
        left_lo_ = _mm_min_ps(pick(centre, none_lo), left_lo_);
        left_hi_ = _mm_max_ps(pick(centre, none_hi), left_hi_);
        right_lo_ = _mm_min_ps(pick(none_lo, centre), right_lo_);
        right_hi_ = _mm_max_ps(pick(none_hi, centre), right_hi_);
    }
    void write(Box& left, Box& right) const {
        store(left_lo_, left_hi_, left);
        store(right_lo_, right_hi_, right);
    }

private:
    static void store(__m128 lo, __m128 hi, Box& box) {
        alignas(16) float l[4];
        alignas(16) float h[4];
        _mm_store_ps(l, lo);
        _mm_store_ps(h, hi);
        for (int k = 0; k < 3; ++k) {
            box.lo[k] = l[k];
            box.hi[k] = h[k];
        }
    }
    __m128 left_lo_ = _mm_set1_ps(HUGE_VALF);
    __m128 left_hi_ = _mm_set1_ps(-HUGE_VALF);
    __m128 right_lo_ = _mm_set1_ps(HUGE_VALF);
    __m128 right_hi_ = _mm_set1_ps(-HUGE_VALF);
};
#else
class CentroidBoxes {
public:
    void grow(bool left, const PolygonReference& ref) {
        grow_by_centroid(left ? left_ : right_, ref);
    }
    void write(Box& left, Box& right) const {
        left = left_;
        right = right_;
    }

private:
    Box left_;
    Box right_;
};
#endif

// References judged at a time from each end of a range by the block partition.
constexpr std::ptrdiff_t kPartitionBlock = 32;

// Moves the references whose bin on `axis` is below `split` before the others, with the swaps
// std::partition makes (so the order, and the tree, do not depend on the library), and finds
// each side's box of centres. Returns where the right side begins.
//
// Which side a reference goes to is a coin toss in a soup, and a loop that branches on it
// mispredicts every other reference. So the range is partitioned by blocks (Edelkamp and Weiss's
// BlockQuicksort): a block from each end is judged without a branch, noting where its misplaced
// references are, and then those are swapped pairwise. The k-th misplaced reference from the
// left meets the k-th from the right, as in the loop, so the swaps are the loop's, and so is the
// tree. What is left, under two blocks, goes through the loop; a reference it judges a second
// time grows its side's box by the same centre again, which changes nothing.
std::uint32_t partition_by_bin(std::span<PolygonReference> refs, const ReferenceRange& r,
                               const Binner& binner, int axis, int split, Box& left_centroids,
                               Box& right_centroids) {
    PolygonReference* first = refs.data() + r.begin;
    PolygonReference* last = refs.data() + r.end;
    CentroidBoxes boxes;
    const auto goes_left = [&](const PolygonReference& ref) {
        const bool left = binner(ref.centroid(axis)) < split;
        boxes.grow(left, ref);
        return left;
    };
    // Offsets of the misplaced references in the current left and right blocks; the right
    // block's count back from `last`. Only the entries below the counts are read.
    std::array<std::uint8_t, kPartitionBlock> misplaced_left;   // NOLINT(*-pro-type-member-init)
    std::array<std::uint8_t, kPartitionBlock> misplaced_right;  // NOLINT(*-pro-type-member-init)
    int left_start = 0;
    int left_count = 0;
    int right_start = 0;
    int right_count = 0;
    while (last - first > 2 * kPartitionBlock) {
        if (left_count == 0) {
            left_start = 0;
            for (int i = 0; i < kPartitionBlock; ++i) {
                misplaced_left[left_count] = static_cast<std::uint8_t>(i);
                left_count += goes_left(first[i]) ? 0 : 1;
            }
        }
        if (right_count == 0) {
            right_start = 0;
            for (int i = 0; i < kPartitionBlock; ++i) {
                misplaced_right[right_count] = static_cast<std::uint8_t>(i);
                right_count += goes_left(*(last - 1 - i)) ? 1 : 0;
            }
        }
        const int pairs = std::min(left_count, right_count);
        for (int j = 0; j < pairs; ++j) {
            std::swap(first[misplaced_left[left_start + j]],
                      *(last - 1 - misplaced_right[right_start + j]));
        }
        left_count -= pairs;
        right_count -= pairs;
        left_start += pairs;
        right_start += pairs;
        if (left_count == 0) {
            first += kPartitionBlock;
        }
        if (right_count == 0) {
            last -= kPartitionBlock;
        }
    }
    const auto done = [&] {
        boxes.write(left_centroids, right_centroids);
        return static_cast<std::uint32_t>(first - refs.data());
    };
    for (;;) {
        for (;; ++first) {
            if (first == last) {
                return done();
            }
            if (!goes_left(*first)) {
                break;
            }
        }
        --last;
        for (;; --last) {
            if (first == last) {
                return done();
            }
            if (goes_left(*last)) {
                break;
            }
        }
        std::swap(*first, *last);
        ++first;
    }
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
        grow_by_centroid(r.centroids, refs[i]);
        r.triangles += refs[i].triangles;
    }
    return r;
}

namespace {

// Whether the surface area heuristic makes `range` a leaf whatever its best split, so that its
// bins need not be made: every split costs 0 or more, so a leaf of at most as many packets as the
// traversal cost of a node is never dearer than the split and the node. That is every range of
// up to 8 triangles, about a third of the ranges split_range is asked about on a mesh; binning
// and sweeping them found the same leaves.
bool always_a_leaf(const ReferenceRange& range) {
    return range.triangles <= kMaxLeafTriangles && packets(range.triangles) <= kTraversalCost;
}

}  // namespace

SplitDecision split_range(std::span<PolygonReference> refs, const ReferenceRange& range,
                          bool by_median, unsigned threads) {
    if (range.size() <= 1 || (!by_median && always_a_leaf(range))) {
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
    bins.clear(count);
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
    SplitDecision split;
    split.leaf = false;
    split.left = side_of(bins, best.axis, 0, best.bin, range.begin);
    split.right = side_of(bins, best.axis, best.bin, count, split.left.end);
    [[maybe_unused]] const std::uint32_t middle =
        partition_by_bin(refs, range, binners[best.axis], best.axis, best.bin, split.left.centroids,
                         split.right.centroids);
    assert(middle == split.left.end);
    return split;
}

}  // namespace rt::bvh
