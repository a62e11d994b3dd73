// Packets of eight coherent rays through the BVH (issue 15): one walk for the packet, each node's
// children tested against the eight rays at once (one AVX2 lane per ray), each leaf's fan
// triangles pre-filtered for the eight rays at once, and every hit still decided per ray by the
// exact intersect_polygon. The box and triangle tests are lane for lane the single ray's
// operations (bvh_traversal.cpp, packet_prefilter.h), so a ray in a packet meets a superset of
// the candidates it meets alone (it may be carried into a box its packet enters), and the exact
// test with brute force's order (hit.h) picks the same hit: each answer is the single ray's.
// A subtree entered by few lanes is walked by each of them alone (single_ray_walk.h).
// Without AVX2 the packet is answered ray by ray.
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "rt/accel/bvh/bvh.h"
#include "rt/accel/bvh/packet_lane.h"
#include "rt/accel/bvh/packet_setup.h"
#include "rt/accel/bvh/prefetch_child.h"
#include "rt/accel/bvh/single_ray_walk.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/accel/lane_exact_hit.h"
#include "rt/core/prefetch.h"
#include "rt/geometry/ray_polygon.h"

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include "rt/accel/bvh/packet_node_tests.h"
#include "rt/accel/bvh/packet_triangle_tests.h"

#include <immintrin.h>
#define RT_BVH_PACKETS_AVX2 1
#endif

namespace rt {

#ifdef RT_BVH_PACKETS_AVX2

namespace {

using bvh::kLastPacketBit;
using bvh::prefetch_child;
using bvh::packet::bound_packet;
using bvh::packet::ChildHits;
using bvh::packet::children_packet_may_meet;
using bvh::packet::first_packet;
using bvh::packet::inner_node;
using bvh::packet::kNodeWidth;
using bvh::packet::lane_triangle_candidate;
using bvh::packet::lanes_max;
using bvh::packet::PacketBounds;
using bvh::packet::test_children;
using bvh::packet::triangle_rays;

const bool cpu_has_avx2 = __builtin_cpu_supports("avx2");

// The builder keeps the tree below 56 levels; each level pushes at most seven siblings.
constexpr int kStackSize = 512;

// A subtree entered by this many lanes or fewer is walked by each lane alone. Lab, one thread,
// against 1 (alone only): camera packets the same on spheres and twocubes and 8 % faster on the
// 100k soup; random packets 15-35 % faster on the 1k meshes. 3 and 4 gave no more.
constexpr int kFewLanes = 2;

using Lane = bvh::PacketLane;

using bvh::PacketValues;

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

// Calls visit(lane, packet, t, id, sure) for each lane in `rays` and each of the leaf's fan
// triangles the pre-filter cannot rule out for it, once per run of equal ids per lane; `sure` when
// the pre-filter found the lane's line surely crossing that triangle. Lanes whose bit
// visit clears in `rays` are asked no further.
template <class Visit>
[[gnu::always_inline]] inline void for_each_leaf_candidate(const bvh::PacketArray& packets,
                                                           const Scene& scene, std::uint32_t leaf,
                                                           const PacketValues& v,
                                                           std::array<Lane, kPacketSize>& lanes,
                                                           std::uint32_t& rays, Visit visit) {
    for (int lane = 0; lane < kPacketSize; ++lane) {
        lanes[lane].previous = ~0u;
    }
    for (std::uint32_t index = first_packet(leaf); rays != 0; ++index) {
        const bvh::TrianglePacket& packet = packets[index];
        bvh::prefetch_exact_data(scene, packet, 3);
        for (int t = 0; t < 4 && rays != 0; ++t) {
            const std::uint32_t id = packet.polygon[t] & ~kLastPacketBit;
            std::uint32_t candidates = 0;
            std::uint32_t sure = 0;
            if (v.same_axes) {
                const bvh::FanVerdicts verdicts = triangle_rays(packet, t, v);
                candidates = verdicts.maybe & rays;
                sure = verdicts.sure;
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
                    visit(lane, packet, t, id, ((sure >> lane) & 1u) != 0);
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

// Few lanes left in the subtree at `child`: each goes on alone, with the single ray's walk,
// which tests a node's eight children at once where the packet tests them a child at a time. It
// offers each lane the single ray's candidates, so its answer stays the single ray's. The lane's
// float form is taken from the packet's values, which set_up_packet made bit for bit the
// single ray's: building it again from the ray cost three divisions a lane.
__attribute__((target("avx2"))) void go_on_alone(const bvh::Hierarchy& tree, const Scene& scene,
                                                 std::uint32_t child, PacketValues& v,
                                                 PacketBounds& b,
                                                 std::array<Lane, kPacketSize>& lanes,
                                                 std::uint32_t rays, TraceCounters& counters) {
    for (std::uint32_t r = rays; r != 0; r &= r - 1) {
        const int lane = std::countr_zero(r);
        Lane& l = lanes[lane];
        bvh::nearest_below(tree, scene, child, bvh::lane_float_ray(v, lane), l.interval(), l,
                           counters);
        v.t_max[lane] = bvh::lane_scaled_up(v, lane, l.best().reach());
    }
    b.t_max = lanes_max(_mm256_load_ps(v.t_max));
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
            if (std::popcount(rays) <= kFewLanes) {
                go_on_alone(tree, scene, child, v, b, lanes, rays, counters);
                child = bvh::kNoChild;
                break;
            }
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
            std::uint32_t found = 0;  // lanes whose nearest hit may have moved
            for_each_leaf_candidate(
                tree.packets, scene, child, v, lanes, leaf_rays,
                [&](int lane, const bvh::TrianglePacket& packet, int t, std::uint32_t id,
                    bool sure) {
                    if (lanes[lane].offer(scene, &packet, t, id, sure, counters)) {
                        found |= 1u << lane;
                    }
                });
            if (found != 0) {
                for (std::uint32_t r = found; r != 0; r &= r - 1) {
                    const int lane = std::countr_zero(r);
                    v.t_max[lane] = bvh::lane_scaled_up(v, lane, lanes[lane].best().reach());
                }
                b.t_max = lanes_max(_mm256_load_ps(v.t_max));
            }
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
                [&](int lane, const bvh::TrianglePacket& p, int t, std::uint32_t id, bool sure) {
                    if ((open >> lane & 1u) == 0) {
                        return;
                    }
                    if (lanes[lane].blocks(scene, p, t, id, sure, packet.t[lane], counters)) {
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

bool Bvh::walks_packets() const {
    return cpu_has_avx2;
}

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
            l.offer(scene_, nullptr, 0, id, false, counters);
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

bool Bvh::walks_packets() const {
    return false;
}

#endif

}  // namespace rt
