// The bounding volume hierarchy (not in the 1988 program; issue 4): a 4-wide SAH tree, collapsed
// to 8-wide, traversed front to back with conservative float box tests and a float pre-filter of
// the leaves' fan triangles, every hit decided by the exact intersect_polygon, so its answers
// equal brute force's bit for bit. docs/accelerators.md describes it.
#pragma once

#include <memory>

#include "rt/accel/accelerator.h"
#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/tree_cost.h"

namespace rt {

struct BvhSettings {
    unsigned build_threads = 0;  ///< 0: one per hardware thread
};

class Bvh : public Accelerator {
public:
    /// Keeps a reference to the scene, which must outlive it.
    explicit Bvh(const Scene& scene, const BvhSettings& settings = {});
    std::string_view name() const override { return "bvh"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;
    /// Eight rays walk the tree together (bvh_packet_traversal.cpp); each answer is the single
    /// ray's.
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override;
    std::uint32_t occluded_packet(const RayPacket& packet, TraceCounters& counters) const override;
    /// True where the CPU has AVX2; without it a packet is asked lane by lane.
    bool walks_packets() const override;
    std::size_t memory_bytes() const override;

    /// For tests and the lab: the tree's size.
    std::size_t node_count() const { return tree_.wide.size(); }
    std::size_t packet_count() const { return tree_.packets.size(); }
    /// The tree's expected cost in Embree's measure (tree_cost.h).
    bvh::TreeCost tree_cost() const { return bvh::tree_cost(tree_); }
    /// How many leaves a line through the scene crosses on average (tree_cost.h), and whether a
    /// single ray therefore asks for the polygon records of the first leaf it enters.
    double leaves_a_line_crosses() const { return bvh::leaves_a_line_crosses(tree_); }
    bool asks_first_leaf_records() const { return tree_.first_leaf_records; }

private:
    const Scene& scene_;
    bvh::Hierarchy tree_;
    std::vector<std::uint32_t> unbounded_;  ///< polygons every ray tests (non-finite corners)
};

std::unique_ptr<Accelerator> make_bvh(const Scene& scene, const BvhSettings& settings = {});

}  // namespace rt
