// Packets of eight coherent rays through the BVH (issue 15): one walk for the packet, each node's
// children tested against the eight rays at once (one AVX2 lane per ray), each leaf's fan
// triangles pre-filtered for the eight rays at once, and every hit still decided per ray by the
// exact intersect_polygon. The box and triangle tests are lane for lane the single ray's
// operations (bvh_traversal.cpp, packet_prefilter.h), so a ray in a packet meets a superset of
// the candidates it meets alone (it may be carried into a box its packet enters), and the exact
// test with brute force's order (hit.h) picks the same hit: each answer is the single ray's.
// Without AVX2 the packet is answered ray by ray.
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "rt/accel/bvh/bvh.h"
#include "rt/accel/bvh/packet_setup.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/geometry/ray_polygon.h"

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define RT_BVH_PACKETS_AVX2 1
#endif

namespace rt {

#ifdef RT_BVH_PACKETS_AVX2

namespace {

using bvh::kLastPacketBit;
using bvh::kLeafBit;

const bool cpu_has_avx2 = __builtin_cpu_supports("avx2");

// The node layout as the packet walk reads it; bvh_layout.h may change under these.
inline const bvh::WideNode& inner_node(const bvh::Hierarchy& tree, std::uint32_t child) {
    return tree.wide[child];
}
/// The eight children's lower (upper) planes on an axis, 32-byte aligned.
inline const float* lower_planes(const bvh::WideNode& node, int axis) {
    return node.lo[axis];
}
inline const float* upper_planes(const bvh::WideNode& node, int axis) {
    return node.hi[axis];
}
inline float child_lo(const bvh::WideNode& node, int axis, int k) {
    return node.lo[axis][k];
}
inline float child_hi(const bvh::WideNode& node, int axis, int k) {
    return node.hi[axis][k];
}
inline std::uint32_t child_word(const bvh::WideNode& node, int k) {
    return node.child[k];
}
constexpr int kNodeWidth = 8;
inline std::uint32_t first_packet(std::uint32_t leaf) {
    return leaf & ~kLeafBit;
}

// The builder keeps the tree below 56 levels; each level pushes at most seven siblings.
constexpr int kStackSize = 512;

// One lane's ray: its float form for the filters, its exact form prepared on its first exact
// test, and its nearest hit so far in brute force's order.
// Nothing is initialised until the lane is started: zeroing eight lanes of a packet took half
// of closest_hit_packet's own time.
class Lane {
public:
    Lane() {}  // NOLINT(cppcoreguidelines-pro-type-member-init,modernize-use-equals-default)
    /// For a nearest hit over `t`.
    void start(const Ray& ray, Interval t) {
        start(ray);
        new (&best_) ClosestHitSoFar(t);
    }
    /// For occlusion alone: best() is not to be used.
    void start(const Ray& ray) {
        ray_ = &ray;
        has_space_ = false;
    }
    const RaySpace& space() {
        if (!has_space_) {
            new (&space_) RaySpace(*ray_);
            has_space_ = true;
        }
        return space_;
    }
    ClosestHitSoFar& best() { return best_; }
    const Ray& ray() const { return *ray_; }

    std::uint32_t previous;  ///< the polygon last offered: fan triangles are adjacent

private:
    const Ray* ray_;
    bool has_space_;
    union {
        RaySpace space_;  ///< prepared on the lane's first exact test
    };
    union {
        ClosestHitSoFar best_;
    };
};

using bvh::PacketValues;

// The packet as a whole, for a test of a node's eight boxes at once that rejects a child only
// when every lane's own test would (interval arithmetic over the lanes): on each axis the range
// of the lanes' origins and inverses (one sign for all, else `usable` is false), the largest
// margin, and the widest t interval.
struct alignas(32) PacketBounds {
    bool usable = false;
    bool negative[3]{};  ///< the lanes' common sign of the inverse on each axis
    float origin_lo[3]{};
    float origin_hi[3]{};
    float inverse_lo[3]{};
    float inverse_hi[3]{};
    float margin[3]{};
    float t_min = 0.0f;  ///< the smallest lane t_min
    float t_max = 0.0f;  ///< the largest lane t_max
};

// Smallest and largest of eight lanes.
__attribute__((target("avx2"))) inline float lanes_min(__m256 x) {
    x = _mm256_min_ps(x, _mm256_permute2f128_ps(x, x, 1));
    x = _mm256_min_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(1, 0, 3, 2)));
    x = _mm256_min_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm256_cvtss_f32(x);
}
__attribute__((target("avx2"))) inline float lanes_max(__m256 x) {
    x = _mm256_max_ps(x, _mm256_permute2f128_ps(x, x, 1));
    x = _mm256_max_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(1, 0, 3, 2)));
    x = _mm256_max_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm256_cvtss_f32(x);
}

// The bounds over every lane; inactive lanes hold copies of an active one (fill_inactive_lanes),
// so all eight count.
__attribute__((target("avx2"))) void bound_packet(const PacketValues& v, PacketBounds& b) {
    b.usable = true;
    for (int k = 0; k < 3; ++k) {
        const __m256 inverse = _mm256_load_ps(v.inverse[k]);
        const int signs = _mm256_movemask_ps(inverse);
        if (signs != 0 && signs != 0xff) {
            b.usable = false;
        }
        b.negative[k] = signs != 0;
        const __m256 origin = _mm256_load_ps(v.origin[k]);
        b.origin_lo[k] = lanes_min(origin);
        b.origin_hi[k] = lanes_max(origin);
        b.inverse_lo[k] = lanes_min(inverse);
        b.inverse_hi[k] = lanes_max(inverse);
        b.margin[k] = lanes_max(_mm256_load_ps(v.margin[k]));
    }
    b.t_min = lanes_min(_mm256_load_ps(v.t_min));
    b.t_max = lanes_max(_mm256_load_ps(v.t_max));
}

// The children some lane of the packet may meet: bit c clear only when every lane's own test
// (test_children) rejects child c. Each step of a lane's test is monotone in each operand
// (correctly rounded operations are; the slack multiplies by a power of two, exactly), so its
// entry is at least this entry, taken with the operands' bounds, and its exit at most this exit.
// A NaN bound keeps the child.
__attribute__((target("avx2"))) std::uint32_t children_packet_may_meet(const bvh::WideNode& node,
                                                                       const PacketBounds& b) {
    __m256 entry = _mm256_set1_ps(-HUGE_VALF);
    __m256 exit = _mm256_set1_ps(HUGE_VALF);
    for (int k = 0; k < 3; ++k) {
        const __m256 lower = _mm256_load_ps(lower_planes(node, k));
        const __m256 upper = _mm256_load_ps(upper_planes(node, k));
        const __m256 near_plane = b.negative[k] ? upper : lower;
        const __m256 far_plane = b.negative[k] ? lower : upper;
        const __m256 o_lo = _mm256_set1_ps(b.origin_lo[k]);
        const __m256 o_hi = _mm256_set1_ps(b.origin_hi[k]);
        const __m256 i_lo = _mm256_set1_ps(b.inverse_lo[k]);
        const __m256 i_hi = _mm256_set1_ps(b.inverse_hi[k]);
        const __m256 margin = _mm256_set1_ps(b.margin[k]);
        const __m256 near_a = _mm256_sub_ps(near_plane, o_hi);
        const __m256 near_b = _mm256_sub_ps(near_plane, o_lo);
        const __m256 far_a = _mm256_sub_ps(far_plane, o_hi);
        const __m256 far_b = _mm256_sub_ps(far_plane, o_lo);
        const __m256 near_low =
            _mm256_min_ps(_mm256_min_ps(_mm256_mul_ps(near_a, i_lo), _mm256_mul_ps(near_a, i_hi)),
                          _mm256_min_ps(_mm256_mul_ps(near_b, i_lo), _mm256_mul_ps(near_b, i_hi)));
        const __m256 far_high =
            _mm256_max_ps(_mm256_max_ps(_mm256_mul_ps(far_a, i_lo), _mm256_mul_ps(far_a, i_hi)),
                          _mm256_max_ps(_mm256_mul_ps(far_b, i_lo), _mm256_mul_ps(far_b, i_hi)));
        entry = _mm256_max_ps(_mm256_sub_ps(near_low, margin), entry);
        exit = _mm256_min_ps(_mm256_add_ps(far_high, margin), exit);
    }
    const __m256 slack = _mm256_set1_ps(kRelativeSlack);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    entry = _mm256_sub_ps(entry, _mm256_mul_ps(_mm256_andnot_ps(sign, entry), slack));
    exit = _mm256_add_ps(exit, _mm256_mul_ps(_mm256_andnot_ps(sign, exit), slack));
    const __m256 rejected =
        _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(entry, exit, _CMP_GT_OQ),
                                  _mm256_cmp_ps(entry, _mm256_set1_ps(b.t_max), _CMP_GT_OQ)),
                     _mm256_cmp_ps(exit, _mm256_set1_ps(b.t_min), _CMP_LT_OQ));
    return ~static_cast<std::uint32_t>(_mm256_movemask_ps(rejected)) & 0xffu;
}

// Gives each inactive lane the values of the first active one: the packet's bounds and every
// lanewise test may then use all eight lanes (the results stay masked by the active lanes).
void fill_inactive_lanes(PacketValues& v, std::uint32_t active) {
    const int from = std::countr_zero(active);
    for (std::uint32_t idle = ~active & 0xffu; idle != 0; idle &= idle - 1) {
        const int lane = std::countr_zero(idle);
        for (int k = 0; k < 3; ++k) {
            v.origin[k][lane] = v.origin[k][from];
            v.inverse[k][lane] = v.inverse[k][from];
            v.margin[k][lane] = v.margin[k][from];
        }
        v.t_min[lane] = v.t_min[from];
        v.t_max[lane] = v.t_max[from];
        v.shear_x[lane] = v.shear_x[from];
        v.shear_y[lane] = v.shear_y[from];
        v.edge_linear[lane] = v.edge_linear[from];
        v.edge_constant[lane] = v.edge_constant[from];
        v.scale_t[lane] = v.scale_t[from];
        v.kx[lane] = v.kx[from];
        v.ky[lane] = v.ky[from];
        v.kz[lane] = v.kz[from];
    }
}

// The exact test of a packet lane's polygon, as bvh_traversal.cpp's exact_hit: a triangle's
// corners from the packet's copy of its indices.
std::optional<double> exact_hit(const RaySpace& space, const Scene& scene,
                                const bvh::TrianglePacket& packet, int lane, std::uint32_t id,
                                Interval t) {
    if (packet.position[0][lane] != bvh::kNotTriangle) {
        const std::uint32_t ids[3] = {packet.position[0][lane], packet.position[1][lane],
                                      packet.position[2][lane]};
        return intersect_polygon(space,
                                 PolygonView{scene.positions, ids, scene.polygons[id].normal}, t);
    }
    return intersect_polygon(space, scene.polygon_view(id), t);
}

struct alignas(32) ChildHits {
    std::uint32_t child = 0;
    std::uint32_t rays = 0;  ///< lanes whose line meets the box within their interval
    float key = 0.0f;        ///< the nearest of those lanes' entries: the visiting order
    alignas(32) float entry[8];
};

// Each child's box against the eight rays: the single ray's test (bvh_traversal.cpp,
// test_wide_boxes_avx2), the same operations in the same order per lane, with the near and far
// planes chosen per lane by the sign of its inverse, for the children in `children` (bits).
// Returns how many of them some lane meets.
__attribute__((target("avx2"))) int test_children(const bvh::WideNode& node, const PacketValues& v,
                                                  std::uint32_t active, std::uint32_t children,
                                                  ChildHits* out) {
    const __m256 slack = _mm256_set1_ps(kRelativeSlack);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    const __m256 t_min = _mm256_load_ps(v.t_min);
    const __m256 t_max = _mm256_load_ps(v.t_max);
    __m256 origin[3];
    __m256 inverse[3];
    __m256 margin[3];
    for (int k = 0; k < 3; ++k) {
        origin[k] = _mm256_load_ps(v.origin[k]);
        inverse[k] = _mm256_load_ps(v.inverse[k]);
        margin[k] = _mm256_load_ps(v.margin[k]);
    }
    int count = 0;
    for (; children != 0; children &= children - 1) {
        const int c = std::countr_zero(children);
        const std::uint32_t child = child_word(node, c);
        if (child == bvh::kNoChild) {
            continue;
        }
        __m256 entry = _mm256_set1_ps(-HUGE_VALF);
        __m256 exit = _mm256_set1_ps(HUGE_VALF);
        for (int k = 0; k < 3; ++k) {
            const __m256 lo = _mm256_set1_ps(child_lo(node, k, c));
            const __m256 hi = _mm256_set1_ps(child_hi(node, k, c));
            // blendv takes its second operand where the inverse's sign bit is set.
            const __m256 near_side = _mm256_sub_ps(_mm256_blendv_ps(lo, hi, inverse[k]), origin[k]);
            const __m256 far_side = _mm256_sub_ps(_mm256_blendv_ps(hi, lo, inverse[k]), origin[k]);
            entry = _mm256_max_ps(_mm256_sub_ps(_mm256_mul_ps(near_side, inverse[k]), margin[k]),
                                  entry);
            exit =
                _mm256_min_ps(_mm256_add_ps(_mm256_mul_ps(far_side, inverse[k]), margin[k]), exit);
        }
        entry = _mm256_sub_ps(entry, _mm256_mul_ps(_mm256_andnot_ps(sign, entry), slack));
        exit = _mm256_add_ps(exit, _mm256_mul_ps(_mm256_andnot_ps(sign, exit), slack));
        const __m256 hit = _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(entry, exit, _CMP_LE_OQ),
                                                       _mm256_cmp_ps(entry, t_max, _CMP_LE_OQ)),
                                         _mm256_cmp_ps(exit, t_min, _CMP_GE_OQ));
        const auto rays = static_cast<std::uint32_t>(_mm256_movemask_ps(hit)) & active;
        if (rays == 0) {
            continue;
        }
        ChildHits& h = out[count++];
        h.child = child;
        h.rays = rays;
        _mm256_store_ps(h.entry, entry);
        // The smallest entry among the lanes that meet the box.
        const __m256i lanes = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        const __m256 met = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
            _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(rays)), lanes), lanes));
        __m256 m = _mm256_blendv_ps(_mm256_set1_ps(HUGE_VALF), entry, met);
        m = _mm256_min_ps(m, _mm256_permute2f128_ps(m, m, 1));
        m = _mm256_min_ps(m, _mm256_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
        m = _mm256_min_ps(m, _mm256_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
        h.key = _mm256_cvtss_f32(m);
    }
    return count;
}

// One fan triangle (lane `t` of `packet`) against the eight rays, in their common axes: lane for
// lane triangle_candidate's operations (triangle_prefilter.h). Bit k: lane k may hit it.
__attribute__((target("avx2"))) std::uint32_t triangle_rays(const bvh::TrianglePacket& packet,
                                                            int t, const PacketValues& v) {
    const int kx = v.kx[0];
    const int ky = v.ky[0];
    const int kz = v.kz[0];
    const __m256 ox = _mm256_load_ps(v.origin[kx]);
    const __m256 oy = _mm256_load_ps(v.origin[ky]);
    const __m256 oz = _mm256_load_ps(v.origin[kz]);
    const __m256 sx = _mm256_load_ps(v.shear_x);
    const __m256 sy = _mm256_load_ps(v.shear_y);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    __m256 x[3];
    __m256 y[3];
    __m256 size = _mm256_setzero_ps();
    for (int c = 0; c < 3; ++c) {
        const __m256 az = _mm256_sub_ps(_mm256_set1_ps(packet.corner[c][kz][t]), oz);
        x[c] = _mm256_sub_ps(_mm256_sub_ps(_mm256_set1_ps(packet.corner[c][kx][t]), ox),
                             _mm256_mul_ps(sx, az));
        y[c] = _mm256_sub_ps(_mm256_sub_ps(_mm256_set1_ps(packet.corner[c][ky][t]), oy),
                             _mm256_mul_ps(sy, az));
        size = _mm256_max_ps(
            size, _mm256_max_ps(_mm256_andnot_ps(sign, x[c]), _mm256_andnot_ps(sign, y[c])));
    }
    const __m256 e0 = _mm256_sub_ps(_mm256_mul_ps(x[1], y[2]), _mm256_mul_ps(y[1], x[2]));
    const __m256 e1 = _mm256_sub_ps(_mm256_mul_ps(x[2], y[0]), _mm256_mul_ps(y[2], x[0]));
    const __m256 e2 = _mm256_sub_ps(_mm256_mul_ps(x[0], y[1]), _mm256_mul_ps(y[0], x[1]));
    const __m256 margin = _mm256_add_ps(
        _mm256_mul_ps(size, _mm256_add_ps(_mm256_load_ps(v.edge_linear),
                                          _mm256_mul_ps(size, _mm256_set1_ps(kRelativeSlack)))),
        _mm256_load_ps(v.edge_constant));
    const __m256 negative_margin = _mm256_sub_ps(_mm256_setzero_ps(), margin);
    const __m256 all_positive =
        _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(e0, negative_margin, _CMP_GE_OQ),
                                    _mm256_cmp_ps(e1, negative_margin, _CMP_GE_OQ)),
                      _mm256_cmp_ps(e2, negative_margin, _CMP_GE_OQ));
    const __m256 all_negative = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(e0, margin, _CMP_LE_OQ), _mm256_cmp_ps(e1, margin, _CMP_LE_OQ)),
        _mm256_cmp_ps(e2, margin, _CMP_LE_OQ));
    return static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_or_ps(all_positive, all_negative)));
}

// Asks for what the exact tests of a packet's triangles read (the polygon records and the
// triangles' corners) while the pre-filter runs: they are scattered through the scene, and the
// exact test otherwise waits for them.
void prefetch_exact_data(const Scene& scene, const bvh::TrianglePacket& packet) {
    for (int t = 0; t < 4; ++t) {
        __builtin_prefetch(&scene.polygons[packet.polygon[t] & ~kLastPacketBit]);
        if (packet.position[0][t] != bvh::kNotTriangle) {
            for (int c = 0; c < 3; ++c) {
                __builtin_prefetch(&scene.positions[packet.position[c][t]]);
            }
        }
    }
}

// triangle_rays for one lane in its own axes: triangle_candidate's operations
// (triangle_prefilter.h), the corners read from the packet.
bool lane_triangle_candidate(const bvh::TrianglePacket& packet, int t, const PacketValues& v,
                             int lane) {
    const int kx = v.kx[lane];
    const int ky = v.ky[lane];
    const int kz = v.kz[lane];
    const float ox = v.origin[kx][lane];
    const float oy = v.origin[ky][lane];
    const float oz = v.origin[kz][lane];
    float x[3];
    float y[3];
    float size = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float az = packet.corner[c][kz][t] - oz;
        x[c] = (packet.corner[c][kx][t] - ox) - v.shear_x[lane] * az;
        y[c] = (packet.corner[c][ky][t] - oy) - v.shear_y[lane] * az;
        size = std::max(size, std::max(std::fabs(x[c]), std::fabs(y[c])));
    }
    const float e0 = x[1] * y[2] - y[1] * x[2];
    const float e1 = x[2] * y[0] - y[2] * x[0];
    const float e2 = x[0] * y[1] - y[0] * x[1];
    const float margin =
        size * (v.edge_linear[lane] + size * kRelativeSlack) + v.edge_constant[lane];
    const bool all_positive = e0 >= -margin && e1 >= -margin && e2 >= -margin;
    const bool all_negative = e0 <= margin && e1 <= margin && e2 <= margin;
    return all_positive || all_negative;
}

// Calls visit(lane, packet, t, id) for each lane in `rays` and each of the leaf's fan triangles
// the pre-filter cannot rule out for it, once per run of equal ids per lane. Lanes whose bit
// visit clears in `rays` are asked no further.
template <class Visit>
[[gnu::always_inline]] inline void for_each_leaf_candidate(
    const std::vector<bvh::TrianglePacket>& packets, const Scene& scene, std::uint32_t leaf,
    const PacketValues& v, std::array<Lane, kPacketSize>& lanes, std::uint32_t& rays, Visit visit) {
    for (int lane = 0; lane < kPacketSize; ++lane) {
        lanes[lane].previous = ~0u;
    }
    for (std::uint32_t index = first_packet(leaf); rays != 0; ++index) {
        const bvh::TrianglePacket& packet = packets[index];
        prefetch_exact_data(scene, packet);
        for (int t = 0; t < 4 && rays != 0; ++t) {
            const std::uint32_t id = packet.polygon[t] & ~kLastPacketBit;
            std::uint32_t candidates = 0;
            if (v.same_axes) {
                candidates = triangle_rays(packet, t, v) & rays;
            } else {
                for (std::uint32_t r = rays; r != 0; r &= r - 1) {
                    const int lane = std::countr_zero(r);
                    if (lane_triangle_candidate(packet, t, v, lane)) {
                        candidates |= 1u << lane;
                    }
                }
            }
            for (; candidates != 0; candidates &= candidates - 1) {
                const int lane = std::countr_zero(candidates);
                if (lanes[lane].previous != id) {
                    lanes[lane].previous = id;
                    visit(lane, packet, t, id);
                }
            }
        }
        if ((packet.polygon[3] & kLastPacketBit) != 0) {
            break;
        }
    }
}

struct alignas(32) StackEntry {
    float entry[8];
    std::uint32_t child;
    std::uint32_t rays;
};

// Asks for a child's cache lines early, as the single ray's walk does: the packet waits on memory
// more than on arithmetic.
void prefetch_child(const bvh::Hierarchy& tree, std::uint32_t child) {
    const void* at = bvh::is_leaf(child)
                         ? static_cast<const void*>(&tree.packets[first_packet(child)])
                         : static_cast<const void*>(&inner_node(tree, child));
    const int lines = bvh::is_leaf(child) ? 7 : 4;
    for (int line = 0; line < lines; ++line) {
        __builtin_prefetch(static_cast<const char*>(at) + std::ptrdiff_t{64} * line);
    }
}

// Sorts the met children nearest first by key (insertion sort: at most eight).
void order_children(ChildHits* hits, int count) {
    for (int i = 1; i < count; ++i) {
        int j = i;
        while (j > 0 && hits[j].key < hits[j - 1].key) {
            std::swap(hits[j], hits[j - 1]);
            --j;
        }
    }
}

__attribute__((target("avx2"))) std::uint32_t still_reaching(const StackEntry& e,
                                                             const PacketValues& v) {
    const __m256 reach =
        _mm256_cmp_ps(_mm256_load_ps(e.entry), _mm256_load_ps(v.t_max), _CMP_LE_OQ);
    return static_cast<std::uint32_t>(_mm256_movemask_ps(reach)) & e.rays;
}

// Front to back for the packet: the nearest child (by its lanes' nearest entry) first, the
// others pushed with their lanes and entries; a popped child keeps only the lanes whose nearest
// hit so far is not before its entry.
__attribute__((target("avx2"), flatten)) void nearest_for_packet(
    const bvh::Hierarchy& tree, const Scene& scene, PacketValues& v,
    std::array<Lane, kPacketSize>& lanes, std::uint32_t active, TraceCounters& counters) {
    PacketBounds b;
    bound_packet(v, b);
    std::array<StackEntry, kStackSize> stack;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    std::array<ChildHits, kNodeWidth> hits;    // NOLINT(cppcoreguidelines-pro-type-member-init)
    int size = 0;
    std::uint32_t child = tree.root;
    std::uint32_t rays = active;
    for (;;) {
        while (child != bvh::kNoChild && !bvh::is_leaf(child)) {
            counters.nodes_visited += std::popcount(rays);
            const bvh::WideNode& node = inner_node(tree, child);
            const std::uint32_t children = b.usable ? children_packet_may_meet(node, b) : 0xffu;
            const int count = test_children(node, v, rays, children, hits.data());
            if (count == 0) {
                child = bvh::kNoChild;
                break;
            }
            order_children(hits.data(), count);
            prefetch_child(tree, hits[0].child);
            for (int i = count - 1; i > 0; --i) {
                prefetch_child(tree, hits[i].child);
                StackEntry& e = stack[size++];
                std::copy(hits[i].entry, hits[i].entry + 8, e.entry);
                e.child = hits[i].child;
                e.rays = hits[i].rays;
            }
            child = hits[0].child;
            rays = hits[0].rays;
        }
        if (child != bvh::kNoChild) {
            std::uint32_t leaf_rays = rays;
            for_each_leaf_candidate(
                tree.packets, scene, child, v, lanes, leaf_rays,
                [&](int lane, const bvh::TrianglePacket& packet, int t, std::uint32_t id) {
                    Lane& l = lanes[lane];
                    ++counters.polygon_tests;
                    const std::optional<double> hit =
                        exact_hit(l.space(), scene, packet, t, id, l.best().search_interval());
                    if (hit) {
                        l.best().offer(*hit, id);
                    }
                });
            for (std::uint32_t r = rays; r != 0; r &= r - 1) {
                const int lane = std::countr_zero(r);
                v.t_max[lane] = bvh::lane_scaled_up(v, lane, lanes[lane].best().reach());
            }
            b.t_max = lanes_max(_mm256_load_ps(v.t_max));
        }
        child = bvh::kNoChild;
        while (size > 0 && child == bvh::kNoChild) {
            const StackEntry& e = stack[--size];
            const std::uint32_t reaching = still_reaching(e, v);
            if (reaching != 0) {
                child = e.child;
                rays = reaching;
            }
        }
        if (child == bvh::kNoChild) {
            return;
        }
    }
}

// Depth first for the packet until every lane is blocked. Returns the blocked lanes.
__attribute__((target("avx2"), flatten)) std::uint32_t blocked_in_packet(
    const bvh::Hierarchy& tree, const Scene& scene, PacketValues& v,
    std::array<Lane, kPacketSize>& lanes, const RayPacket& packet, std::uint32_t active,
    TraceCounters& counters) {
    PacketBounds b;
    bound_packet(v, b);
    struct Entry {
        std::uint32_t child;
        std::uint32_t rays;
    };
    std::array<Entry, kStackSize> stack;     // NOLINT(cppcoreguidelines-pro-type-member-init)
    std::array<ChildHits, kNodeWidth> hits;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    std::uint32_t open = active;             // lanes not yet blocked
    int size = 0;
    stack[size++] = {tree.root, active};
    while (size > 0 && open != 0) {
        const Entry e = stack[--size];
        const std::uint32_t rays = e.rays & open;
        if (rays == 0) {
            continue;
        }
        if (bvh::is_leaf(e.child)) {
            std::uint32_t leaf_rays = rays;
            for_each_leaf_candidate(
                tree.packets, scene, e.child, v, lanes, leaf_rays,
                [&](int lane, const bvh::TrianglePacket& p, int t, std::uint32_t id) {
                    Lane& l = lanes[lane];
                    if ((open >> lane & 1u) == 0) {
                        return;
                    }
                    ++counters.polygon_tests;
                    if (exact_hit(l.space(), scene, p, t, id, packet.t[lane]).has_value()) {
                        open &= ~(1u << lane);
                        leaf_rays &= ~(1u << lane);
                    }
                });
            continue;
        }
        counters.nodes_visited += std::popcount(rays);
        const bvh::WideNode& node = inner_node(tree, e.child);
        const std::uint32_t children = b.usable ? children_packet_may_meet(node, b) : 0xffu;
        const int count = test_children(node, v, rays, children, hits.data());
        for (int i = 0; i < count; ++i) {
            prefetch_child(tree, hits[i].child);
            stack[size++] = {hits[i].child, hits[i].rays};
        }
    }
    return active & ~open;
}

}  // namespace

void Bvh::closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                             TraceCounters& counters) const {
    if (!cpu_has_avx2 || tree_.root == bvh::kNoChild) {
        Accelerator::closest_hit_packet(packet, hits, counters);
        return;
    }
    std::array<Lane, kPacketSize> lanes;
    PacketValues values;  // NOLINT(cppcoreguidelines-pro-type-member-init): set up below
    const std::uint32_t active = bvh::set_up_packet(packet, tree_.scale, values);
    for (std::uint32_t a = packet.active & 0xffu & ~active; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);  // the single ray's path: unusable or extreme
        hits[lane] = closest_hit(packet.rays[lane], packet.t[lane], counters);
    }
    for (std::uint32_t a = active; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        Lane& l = lanes[lane];
        l.start(packet.rays[lane], packet.t[lane]);
        if (unbounded_.empty()) {
            continue;
        }
        for (const std::uint32_t id : unbounded_) {
            ++counters.polygon_tests;
            if (const std::optional<double> hit = intersect_polygon(
                    l.space(), scene_.polygon_view(id), l.best().search_interval())) {
                l.best().offer(*hit, id);
            }
        }
        values.t_max[lane] = bvh::lane_scaled_up(values, lane, l.best().reach());
    }
    if (active != 0) {
        fill_inactive_lanes(values, active);
        nearest_for_packet(tree_, scene_, values, lanes, active, counters);
    }
    for (std::uint32_t a = active; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        hits[lane] = lanes[lane].best().best();
    }
}

std::uint32_t Bvh::occluded_packet(const RayPacket& packet, TraceCounters& counters) const {
    if (!cpu_has_avx2 || tree_.root == bvh::kNoChild || !unbounded_.empty()) {
        return Accelerator::occluded_packet(packet, counters);
    }
    std::array<Lane, kPacketSize> lanes;
    PacketValues values;  // NOLINT(cppcoreguidelines-pro-type-member-init): set up below
    const std::uint32_t active = bvh::set_up_packet(packet, tree_.scale, values);
    std::uint32_t blocked = 0;
    for (std::uint32_t a = packet.active & 0xffu & ~active; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        blocked |= occluded(packet.rays[lane], packet.t[lane], counters) ? 1u << lane : 0u;
    }
    for (std::uint32_t a = active; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        lanes[lane].start(packet.rays[lane]);
    }
    if (active != 0) {
        fill_inactive_lanes(values, active);
        blocked |= blocked_in_packet(tree_, scene_, values, lanes, packet, active, counters);
    }
    return blocked;
}

#else

void Bvh::closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                             TraceCounters& counters) const {
    Accelerator::closest_hit_packet(packet, hits, counters);
}

std::uint32_t Bvh::occluded_packet(const RayPacket& packet, TraceCounters& counters) const {
    return Accelerator::occluded_packet(packet, counters);
}

#endif

}  // namespace rt
