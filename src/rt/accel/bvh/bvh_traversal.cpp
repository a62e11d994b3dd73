// Traversal: closest_hit goes front to back, nearest child first, and skips a child whose box the
// line enters beyond the nearest hit so far (box_test.h); occluded stops at the first hit. Both
// decide every hit with intersect_polygon.
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#endif

#include "rt/accel/bvh/box_test.h"
#include "rt/accel/bvh/bvh.h"
#include "rt/accel/bvh/packet_pair_prefilter.h"
#include "rt/accel/bvh/packet_prefilter.h"
#include "rt/accel/bvh/prefetch_child.h"
#include "rt/accel/bvh/single_ray_walk.h"
#include "rt/accel/float_prefilter/fused_float8.h"
#include "rt/accel/lane_exact_hit.h"
#include "rt/geometry/ray_polygon.h"

namespace rt {

namespace {

using bvh::kLastPacketBit;
using bvh::kLeafBit;

// The builder keeps the tree below 56 levels; each (8-wide) level pushes at most seven siblings.
constexpr int kStackSize = 512;

struct StackEntry {
    std::uint32_t child;
    float entry;  ///< where the ray's line enters the child's box, scaled t
};

// The nearest hit so far, in brute force's order (hit.h). The ray's exact RaySpace is prepared on
// the first exact test: most rays never need one.
class NearestHit {
public:
    NearestHit(const Ray& ray, Interval t) : ray_(ray), best_(t) {}
    void offer(const Scene& scene, std::uint32_t id, TraceCounters& counters) {
        offer(scene, nullptr, 0, id, false, counters);
    }
    /// With `packet` (may be null) the lane of `id` in it, `sure` when the pre-filter found the
    /// ray surely crossing that lane's triangle.
    void offer(const Scene& scene, const bvh::TrianglePacket* packet, int lane, std::uint32_t id,
               bool sure, TraceCounters& counters) {
        if (leaves_polygon(ray_, id)) {
            return;  // before the RaySpace: often the only polygon a ray leaving a surface meets
        }
        ++counters.polygon_tests;
        const Interval search = best_.search_interval();
        std::optional<double> hit;
        if (sure && lane_sure_hit(ray_, scene, packet->position, lane, id, search, hit)) {
            if (hit) {
                best_.offer(*hit, id);
            }
            return;
        }
        if (!space_) {
            // Before the RaySpace, the plane alone (lane_exact_hit.h): a ray leaving a surface
            // beside coplanar neighbours, or a feeler ending on its light, often needs no other.
            if (packet != nullptr
                    ? lane_plane_certainly_missed(ray_, scene, packet->position, lane, id, search)
                    : polygon_plane_certainly_missed(ray_, scene, id, search)) {
                return;
            }
            space_.emplace(ray_);
        }
        hit = packet != nullptr ? lane_exact_hit(*space_, scene, packet->position, lane, id, search)
                                : intersect_polygon(*space_, scene.polygon_view(id), search);
        if (hit) {
            best_.offer(*hit, id);
        }
    }
    const std::optional<Hit>& best() const { return best_.best(); }
    /// The largest t a box must reach to matter, inclusive.
    double reach() const { return best_.reach(); }

private:
    const Ray& ray_;
    std::optional<RaySpace> space_;
    ClosestHitSoFar best_;
};

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define RT_BVH_AVX2 1
const bool cpu_has_avx2 = __builtin_cpu_supports("avx2");

// packet_verdicts of two consecutive packets at once. Bits 4-7: the second.
__attribute__((target("avx2"))) inline bvh::FanVerdicts pair_verdicts_avx2(
    const bvh::TrianglePacket* packet, const FloatRay& ray) {
    return bvh::fan_pair_verdicts(packet[0].corner, packet[1].corner, ray);
}
#endif

// Calls visit(packet, lane, id, sure) for each polygon of the leaf that the pre-filter cannot
// rule out, once per run of equal ids (a polygon's fan triangles are adjacent); `sure` when the
// pre-filter found the ray's line surely crossing that fan triangle. Stops early when visit
// returns true. With AVX2, two packets at a time.
template <bool kAvx2, class Visit>
[[gnu::always_inline]] inline bool for_each_candidate(const bvh::PacketArray& packets,
                                                      std::uint32_t leaf, const FloatRay& ray,
                                                      Visit visit) {
    std::uint32_t previous = ~0u;
    for (std::uint32_t index = leaf & ~kLeafBit;;) {
        const bvh::TrianglePacket* packet = &packets[index];
        const bool last = (packet->polygon[3] & kLastPacketBit) != 0;
#ifdef RT_BVH_AVX2
        const bool pair = kAvx2 && !last;
        const bvh::FanVerdicts verdicts =
            pair ? pair_verdicts_avx2(packet, ray) : bvh::packet_verdicts(*packet, ray);
#else
        const bool pair = false;
        const bvh::FanVerdicts verdicts = bvh::packet_verdicts(*packet, ray);
#endif
        unsigned bits = verdicts.maybe;
        const unsigned sure = verdicts.sure;
        for (; bits != 0; bits &= bits - 1) {
            const int bit = std::countr_zero(bits);
            const bvh::TrianglePacket& p = packet[bit >> 2];
            const int lane = bit & 3;
            const std::uint32_t id = p.polygon[lane] & ~kLastPacketBit;
            if (id != previous) {
                previous = id;
                if (visit(p, lane, id, ((sure >> bit) & 1u) != 0)) {
                    return true;
                }
            }
        }
        if (last || (pair && (packet[1].polygon[3] & kLastPacketBit) != 0)) {
            return false;
        }
        index += pair ? 2 : 1;
    }
}

#ifdef RT_BVH_AVX2
// One layer of a sorting network on eight keys: lane i meets lane partner[i], and the lanes set in
// kUpper keep the larger of the two, the others the smaller.
template <int kUpper>
__attribute__((target("avx2"))) inline __m256i network_layer(__m256i keys, __m256i partner) {
    const __m256i other = _mm256_permutevar8x32_epi32(keys, partner);
    return _mm256_blend_epi32(_mm256_min_epi32(keys, other), _mm256_max_epi32(keys, other), kUpper);
}

// descend for four children or more, the children sorted by a network instead of an insertion
// sort, whose loops mispredicted on random rays (docs/lab/sure-crossings-2026-12-07.md: from
// three children on, camera rays on small meshes ran 2-4 % slower, where the sort predicts well).
// Each met child's key is its entry's float bits made an integer of the same order (a negative
// float's magnitude bits flipped), its lowest three bits replaced by its slot; missed children's
// keys are the largest int. Eight keys sort in six layers of Batcher-style comparisons (19
// comparators, every 0-1 input checked). Entries within eight units in the last place of each other
// may come out in slot order instead of theirs: that changes the order of the walk, never its
// answer (hit.h's order rule).
__attribute__((target("avx2"))) inline std::uint32_t descend_sorted(const bvh::Hierarchy& tree,
                                                                    const bvh::WideNode& node,
                                                                    const bvh::WideHits& hits,
                                                                    int count, StackEntry* stack,
                                                                    int& size) {
    const __m256i entry = _mm256_load_si256(reinterpret_cast<const __m256i*>(hits.entry));
    const __m256i flip = _mm256_srli_epi32(_mm256_srai_epi32(entry, 31), 1);
    const __m256i slot = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    __m256i keys = _mm256_or_si256(
        _mm256_and_si256(_mm256_xor_si256(entry, flip), _mm256_set1_epi32(~7)), slot);
    const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256i met =
        _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(hits.mask), lane_bit), lane_bit);
    keys = _mm256_blendv_epi8(_mm256_set1_epi32(0x7fffffff), keys, met);
    keys = network_layer<0xcc>(keys, _mm256_setr_epi32(2, 3, 0, 1, 6, 7, 4, 5));
    keys = network_layer<0xf0>(keys, _mm256_setr_epi32(4, 5, 6, 7, 0, 1, 2, 3));
    keys = network_layer<0xaa>(keys, _mm256_setr_epi32(1, 0, 3, 2, 5, 4, 7, 6));
    keys = network_layer<0x30>(keys, _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7));
    keys = network_layer<0x50>(keys, _mm256_setr_epi32(0, 4, 2, 6, 1, 5, 3, 7));
    keys = network_layer<0x54>(keys, _mm256_setr_epi32(0, 2, 1, 4, 3, 6, 5, 7));
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-member-init): stored whole below
    alignas(32) std::array<std::uint32_t, 8> sorted;
    _mm256_store_si256(reinterpret_cast<__m256i*>(sorted.data()), keys);
    for (int i = count - 1; i > 0; --i) {
        const std::uint32_t k = sorted[static_cast<std::size_t>(i)] & 7u;
        bvh::prefetch_child(tree, node.child[k]);
        stack[size++] = {node.child[k], hits.entry[k]};
    }
    return node.child[sorted[0] & 7u];
}

#endif

// Orders a pair by entry, nearest first. GCC compiles the choice to a branch; a branch-free
// form (the two words swapped by an XOR under a mask) ran no faster in the lab
// (docs/lab/ray-cost-2026-12-08.md).
void order_pair(StackEntry& a, StackEntry& b) {
    const bool swap = b.entry < a.entry;
    const StackEntry first = swap ? b : a;
    const StackEntry second = swap ? a : b;
    a = first;
    b = second;
}

// Of the children the ray may meet, returns the nearest (by box entry) to descend into and pushes
// the others farthest first, so the next nearest is popped next; kNoChild if none. Forced inline:
// as a call, once per node, it was a sixth of the walk's samples on the soups, and inlined the
// walk goes about 5 % faster there (docs/lab/bvh-partition-2026-12-03.md).
template <bool kAvx2>
[[gnu::always_inline]] inline std::uint32_t descend(const bvh::Hierarchy& tree,
                                                    const bvh::WideNode& node,
                                                    const bvh::WideHits& hits, StackEntry* stack,
                                                    int& size) {
    int bits = hits.mask;
    if (bits == 0) {
        return bvh::kNoChild;
    }
    if ((bits & (bits - 1)) == 0) {  // one child: nothing to order or push
        return node.child[std::countr_zero(static_cast<unsigned>(bits))];
    }
#ifdef RT_BVH_AVX2
    if constexpr (kAvx2) {
        const int met = std::popcount(static_cast<unsigned>(bits));
        if (met > 3) {
            return descend_sorted(tree, node, hits, met, stack, size);
        }
    }
#endif
    // Two and three children without loops, whose exits the predictor misses as the count
    // changes from node to node. Adjacent compare-exchanges sort stably, as the insertion sort.
    {
        int rest = bits;
        const int k0 = std::countr_zero(static_cast<unsigned>(rest));
        rest &= rest - 1;
        const int k1 = std::countr_zero(static_cast<unsigned>(rest));
        rest &= rest - 1;
        StackEntry a{node.child[k0], hits.entry[k0]};
        StackEntry b{node.child[k1], hits.entry[k1]};
        if (rest == 0) {
            order_pair(a, b);
            bvh::prefetch_child(tree, b.child);
            stack[size++] = b;
            return a.child;
        }
        if ((rest & (rest - 1)) == 0) {
            const int k2 = std::countr_zero(static_cast<unsigned>(rest));
            StackEntry c{node.child[k2], hits.entry[k2]};
            order_pair(a, b);
            order_pair(b, c);
            order_pair(a, b);
            bvh::prefetch_child(tree, c.child);
            stack[size++] = c;
            bvh::prefetch_child(tree, b.child);
            stack[size++] = b;
            return a.child;
        }
    }
    std::array<StackEntry, 8> c;  // NOLINT(cppcoreguidelines-pro-type-member-init): filled below
    int count = 0;
    for (; bits != 0; bits &= bits - 1) {
        const int k = std::countr_zero(static_cast<unsigned>(bits));
        c[count++] = {node.child[k], hits.entry[k]};
    }
    // Insertion sort of four to eight (without AVX2; with it, descend_sorted takes them).
    for (int i = 1; i < count; ++i) {
        const StackEntry x = c[i];
        int j = i;
        for (; j > 0 && x.entry < c[j - 1].entry; --j) {
            c[j] = c[j - 1];
        }
        c[j] = x;
    }
    for (int i = count - 1; i > 0; --i) {
        bvh::prefetch_child(tree, c[i].child);
        stack[size++] = c[i];
    }
    return c[0].child;
}

#ifdef RT_BVH_AVX2
// Where the line meets the near and far planes of axis k of the eight boxes at `base` (the node's
// first plane), each plane's product and offset fused into one step where the build has FMA
// (fused_float8.h).
__attribute__((target("avx2"))) inline void axis_planes(const float* base, const bvh::BoxRay& ray,
                                                        int k, __m256& near_t, __m256& far_t) {
    const __m256 inverse = _mm256_set1_ps(_mm_cvtss_f32(ray.inverse[k].v));
    near_t = fused::mul_sub(_mm256_load_ps(base + std::ptrdiff_t{2} * ray.near_plane[k]), inverse,
                            _mm256_set1_ps(_mm_cvtss_f32(ray.near_offset[k].v)));
    far_t = fused::mul_sub(_mm256_load_ps(base + std::ptrdiff_t{2} * ray.far_plane[k]), inverse,
                           _mm256_set1_ps(_mm_cvtss_f32(ray.far_offset[k].v)));
}

// Forced inline in a build for AVX2: calling fused_float8.h's steps, the test below became too
// big for GCC's flatten to take, and stayed a call per node. A build for any x86-64 CPU cannot
// force it (the walk's template is plain code until inlined into its AVX2 caller).
#ifdef __AVX2__
#define RT_INLINE_IN_AVX2_BUILDS [[gnu::always_inline]] inline
#else
#define RT_INLINE_IN_AVX2_BUILDS
#endif

// The same test with one AVX2 register per plane.
RT_INLINE_IN_AVX2_BUILDS __attribute__((target("avx2"))) void test_wide_boxes_avx2(
    const bvh::WideNode& node, const bvh::BoxRay& ray, float t_min, float t_max,
    bvh::WideHits& out) {
    const float* base = node.lo[0];
    // The first axis's values start entry and exit, as in the SSE2 form (box_test.h).
    __m256 entry;
    __m256 exit;
    axis_planes(base, ray, 0, entry, exit);
    for (int k = 1; k < 3; ++k) {
        __m256 near_t;
        __m256 far_t;
        axis_planes(base, ray, k, near_t, far_t);
        entry = _mm256_max_ps(near_t, entry);
        exit = _mm256_min_ps(far_t, exit);
    }
    // No relative widening, as in the SSE2 form: it was two steps on the chain from a node's
    // load to the child the ray goes to next.
    const __m256 hit =
        _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(entry, exit, _CMP_LE_OQ),
                                    _mm256_cmp_ps(entry, _mm256_set1_ps(t_max), _CMP_LE_OQ)),
                      _mm256_cmp_ps(exit, _mm256_set1_ps(t_min), _CMP_GE_OQ));
    out.mask = _mm256_movemask_ps(hit);
    _mm256_store_ps(out.entry, entry);
}

#endif

template <bool kAvx2>
[[gnu::always_inline]] inline void test_wide_boxes(const bvh::WideNode& node,
                                                   const bvh::BoxRay& ray, float t_min, float t_max,
                                                   bvh::WideHits& out) {
#ifdef RT_BVH_AVX2
    if constexpr (kAvx2) {
        test_wide_boxes_avx2(node, ray, t_min, t_max, out);
        return;
    }
#endif
    bvh::test_wide_boxes_sse2(node, ray, simd::Float4::broadcast(t_min),
                              simd::Float4::broadcast(t_max), out);
}

// The nearest hit so far of a packet's lane going on alone (single_ray_walk.h), kept by the
// lane.
class NearestHitElsewhere {
public:
    explicit NearestHitElsewhere(bvh::PacketLane& lane) : lane_(lane) {}
    void offer(const Scene& scene, const bvh::TrianglePacket* packet, int lane, std::uint32_t id,
               bool sure, TraceCounters& counters) {
        lane_.offer(scene, packet, lane, id, sure, counters);
    }
    double reach() { return lane_.best().reach(); }

private:
    bvh::PacketLane& lane_;
};

// Front to back through the tree from `start` (the root, or a node or leaf below it), offering
// each candidate to `nearest`. Compiled twice: as is, and inlined into an AVX2 function, where
// the box and packet tests inline into the loop (a call into an AVX2 function from plain code
// cannot be inlined).
// `deferred`, when not null, is the ray of a FloatRay set up BoxesFirst: its triangle values are
// set up at the first leaf.
template <bool kAvx2, class Nearest>
[[gnu::always_inline]] inline void nearest_in_tree(const bvh::Hierarchy& tree, const Scene& scene,
                                                   FloatRay& fray, const Ray* deferred, Interval t,
                                                   std::uint32_t start, Nearest& nearest,
                                                   TraceCounters& counters) {
    const bvh::BoxRay box_ray(fray);
    const float t_min = fray.scaled_down(t.min);
    float t_max = fray.scaled_up(nearest.reach());
    bvh::WideHits hits;
    // Left uninitialised: zeroing 4 kB per ray costs more than some rays' whole traversal.
    std::array<StackEntry, kStackSize> stack;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    int size = 0;
    std::uint32_t child = start;
    bool first_leaf = true;
    for (;;) {
        while (child != bvh::kNoChild && !bvh::is_leaf(child)) {
            ++counters.nodes_visited;
            const bvh::WideNode& node = tree.wide[child];
            test_wide_boxes<kAvx2>(node, box_ray, t_min, t_max, hits);
            child = descend<kAvx2>(tree, node, hits, stack.data(), size);
        }
        if (child != bvh::kNoChild) {
            if (first_leaf) {
                if (tree.first_leaf_records) {
                    bvh::prefetch_leaf_polygons(tree, scene, child);
                }
                if (deferred != nullptr) {
                    fray.set_up_triangles(*deferred);
                }
                first_leaf = false;
            }
            for_each_candidate<kAvx2>(
                tree.packets, child, fray,
                [&](const bvh::TrianglePacket& packet, int lane, std::uint32_t id, bool sure) {
                    nearest.offer(scene, &packet, lane, id, sure, counters);
                    return false;
                });
            t_max = fray.scaled_up(nearest.reach());
        }
        // The next pushed child that may still hold something nearer.
        child = bvh::kNoChild;
        while (size > 0 && child == bvh::kNoChild) {
            const StackEntry entry = stack[--size];
            if (entry.entry <= t_max) {
                child = entry.child;
            }
        }
        if (child == bvh::kNoChild) {
            break;
        }
    }
}

#ifdef RT_BVH_AVX2
__attribute__((target("avx2"), flatten)) void nearest_in_tree_avx2(const bvh::Hierarchy& tree,
                                                                   const Scene& scene,
                                                                   FloatRay& fray, const Ray& ray,
                                                                   Interval t, NearestHit& nearest,
                                                                   TraceCounters& counters) {
    nearest_in_tree<true>(tree, scene, fray, &ray, t, tree.root, nearest, counters);
}

__attribute__((target("avx2"), flatten)) void nearest_below_avx2(
    const bvh::Hierarchy& tree, const Scene& scene, const FloatRay& fray, Interval t,
    std::uint32_t start, NearestHitElsewhere& nearest, TraceCounters& counters) {
    FloatRay lane_ray = fray;
    nearest_in_tree<true>(tree, scene, lane_ray, nullptr, t, start, nearest, counters);
}
#endif

// Depth first through the tree until a candidate blocks; compiled twice, as nearest_in_tree is.
// `fray` was set up BoxesFirst from `ray`: its triangle values are set up at the first leaf.
template <bool kAvx2, class Blocks>
[[gnu::always_inline]] inline bool any_hit_in_tree(const bvh::Hierarchy& tree, FloatRay& fray,
                                                   const Ray& ray, Interval t,
                                                   const Blocks& blocks_lane,
                                                   TraceCounters& counters) {
    const bvh::BoxRay box_ray(fray);
    const float t_min = fray.scaled_down(t.min);
    const float t_max = fray.scaled_up(t.max);
    bvh::WideHits hits;
    std::array<std::uint32_t, kStackSize> stack;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    int size = 0;
    stack[size++] = tree.root;
    bool first_leaf = true;
    while (size > 0) {
        const std::uint32_t child = stack[--size];
        if (bvh::is_leaf(child)) {
            if (first_leaf) {
                fray.set_up_triangles(ray);
                first_leaf = false;
            }
            if (for_each_candidate<kAvx2>(tree.packets, child, fray, blocks_lane)) {
                return true;
            }
            continue;
        }
        ++counters.nodes_visited;
        const bvh::WideNode& node = tree.wide[child];
        test_wide_boxes<kAvx2>(node, box_ray, t_min, t_max, hits);
        for (int bits = hits.mask; bits != 0; bits &= bits - 1) {
            stack[size++] = node.child[std::countr_zero(static_cast<unsigned>(bits))];
        }
    }
    return false;
}

#ifdef RT_BVH_AVX2
template <class Blocks>
__attribute__((target("avx2"), flatten)) bool any_hit_in_tree_avx2(const bvh::Hierarchy& tree,
                                                                   FloatRay& fray, const Ray& ray,
                                                                   Interval t,
                                                                   const Blocks& blocks_lane,
                                                                   TraceCounters& counters) {
    return any_hit_in_tree<true>(tree, fray, ray, t, blocks_lane, counters);
}
#endif

}  // namespace

std::optional<Hit> Bvh::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    // A usable FloatRay has a finite origin and a finite nonzero direction, so RaySpace would be
    // valid too; an unusable one falls back to testing every polygon (an invalid ray misses all).
    FloatRay fray(ray, tree_.scale, FloatRay::BoxesFirst{});
    NearestHit nearest(ray, t);
    if (!fray.usable) {
        if (RaySpace(ray).valid()) {
            for (std::uint32_t id = 0; id < scene_.polygons.size(); ++id) {
                nearest.offer(scene_, id, counters);
            }
        }
        return nearest.best();
    }
    for (const std::uint32_t id : unbounded_) {
        nearest.offer(scene_, id, counters);
    }
    if (tree_.root == bvh::kNoChild) {
        return nearest.best();
    }
#ifdef RT_BVH_AVX2
    if (cpu_has_avx2) {
        nearest_in_tree_avx2(tree_, scene_, fray, ray, t, nearest, counters);
        return nearest.best();
    }
#endif
    nearest_in_tree<false>(tree_, scene_, fray, &ray, t, tree_.root, nearest, counters);
    return nearest.best();
}

void bvh::nearest_below(const Hierarchy& tree, const Scene& scene, std::uint32_t start,
                        const FloatRay& fray, Interval t, PacketLane& lane,
                        TraceCounters& counters) {
    NearestHitElsewhere nearest(lane);
#ifdef RT_BVH_AVX2
    if (cpu_has_avx2) {
        nearest_below_avx2(tree, scene, fray, t, start, nearest, counters);
        return;
    }
#endif
    FloatRay lane_ray = fray;
    nearest_in_tree<false>(tree, scene, lane_ray, nullptr, t, start, nearest, counters);
}

bool Bvh::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    FloatRay fray(ray, tree_.scale, FloatRay::BoxesFirst{});
    std::optional<RaySpace> space;  // prepared on the first exact test, as in closest_hit
    const auto blocks = [&](std::uint32_t id) {
        if (leaves_polygon(ray, id)) {
            return false;
        }
        ++counters.polygon_tests;
        if (!space) {
            if (polygon_plane_certainly_missed(ray, scene_, id, t)) {
                return false;
            }
            space.emplace(ray);
        }
        return intersect_polygon(*space, scene_.polygon_view(id), t).has_value();
    };
    if (!fray.usable) {
        if (!RaySpace(ray).valid()) {
            return false;
        }
        for (std::uint32_t id = 0; id < scene_.polygons.size(); ++id) {
            if (blocks(id)) {
                return true;
            }
        }
        return false;
    }
    for (const std::uint32_t id : unbounded_) {
        if (blocks(id)) {
            return true;
        }
    }
    if (tree_.root == bvh::kNoChild) {
        return false;
    }
    const auto blocks_lane = [&](const bvh::TrianglePacket& packet, int lane, std::uint32_t id,
                                 bool sure) {
        if (leaves_polygon(ray, id)) {
            return false;
        }
        ++counters.polygon_tests;
        std::optional<double> hit;
        if (sure && lane_sure_hit(ray, scene_, packet.position, lane, id, t, hit)) {
            return hit.has_value();
        }
        if (!space) {
            if (lane_plane_certainly_missed(ray, scene_, packet.position, lane, id, t)) {
                return false;
            }
            space.emplace(ray);
        }
        return lane_exact_hit(*space, scene_, packet.position, lane, id, t).has_value();
    };
#ifdef RT_BVH_AVX2
    if (cpu_has_avx2) {
        return any_hit_in_tree_avx2(tree_, fray, ray, t, blocks_lane, counters);
    }
#endif
    return any_hit_in_tree<false>(tree_, fray, ray, t, blocks_lane, counters);
}

}  // namespace rt
