#include "rt/accel/bvh/leaf_filling.h"

#include <algorithm>
#include <vector>

#include "rt/accel/bvh/leaf_packets.h"
#include "rt/accel/parallel_parts.h"
#include "rt/core/error.h"
#include "rt/core/huge_pages.h"
#include "rt/core/prefetch.h"

namespace rt::bvh {

namespace {

// How many leaves ahead each link of the chain is asked for: the polygon records first, their
// corner lists once the records have had time to arrive, the positions last.
constexpr std::size_t kRecordsAhead = 12;
constexpr std::size_t kCornersAhead = 6;
constexpr std::size_t kPositionsAhead = 2;
// Runs of leaves a build thread fills, on average (fill_leaves).
constexpr std::size_t kRunsPerThread = 8;

std::span<const PolygonReference> refs_of(std::span<const PolygonReference> refs,
                                          const PendingLeaf& leaf) {
    return refs.subspan(leaf.begin, leaf.end - leaf.begin);
}

void point_at(Hierarchy& tree, const PendingLeaf& leaf, std::uint32_t packet) {
    std::uint32_t& word =
        leaf.node == kNoChild ? tree.root : tree.nodes[leaf.node].child[leaf.slot];
    word = kLeafBit | packet;
}

// Writes the leaves' packets from tree.packets[first] on, and points each leaf at its own. Runs on
// several threads at once: each writes its own packets and its own leaves' child words.
void fill_run(const Scene& scene, std::span<const PolygonReference> refs,
              std::span<const PendingLeaf> leaves, std::uint32_t first, Hierarchy& tree) {
    const auto ahead = [&](std::size_t i, auto&& ask) {
        if (i < leaves.size()) {
            for (const PolygonReference& ref : refs_of(refs, leaves[i])) {
                ask(scene.polygons[ref.polygon]);
            }
        }
    };
    std::uint32_t packet = first;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        ahead(i + kRecordsAhead, [](const Polygon& p) { prefetch(&p); });
        ahead(i + kCornersAhead,
              [&](const Polygon& p) { prefetch(scene.corners.data() + p.first_corner); });
        ahead(i + kPositionsAhead, [&](const Polygon& p) {
            for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                prefetch(&scene.positions[scene.corners[p.first_corner + k]]);
            }
        });
        point_at(tree, leaves[i], packet);
        packet += write_leaf_packets(scene, refs_of(refs, leaves[i]), tree.packets.data() + packet);
    }
}

}  // namespace

void fill_leaves(const Scene& scene, std::span<const PolygonReference> refs,
                 std::span<const PendingLeaf> leaves, Hierarchy& tree, unsigned threads) {
    // Runs of whole leaves, in the order given, about as many references each: several a thread,
    // each thread taking the next when done with its last, so that a core slowed by another
    // program holds no other back.
    const std::size_t count = std::clamp<std::size_t>(
        std::size_t{threads} * kRunsPerThread, 1, std::max<std::size_t>(leaves.size() / 4096, 1));
    std::vector<std::size_t> bounds{0};
    std::size_t taken = 0;
    for (std::size_t i = 0; i < leaves.size() && bounds.size() < count; ++i) {
        taken += leaves[i].end - leaves[i].begin;
        if (taken * count >= refs.size() * bounds.size()) {
            bounds.push_back(i + 1);
        }
    }
    while (bounds.size() <= count) {
        bounds.push_back(leaves.size());
    }
    const auto run_leaves = [&](std::size_t r) {
        return leaves.subspan(bounds[r], bounds[r + 1] - bounds[r]);
    };
    // Each run's packets go straight to their place in the tree's one array, sized first (which
    // writes nothing: PacketArray): before, all but the first run's were copied there after.
    std::vector<std::uint32_t> first(count + 1, 0);
    for (std::size_t r = 0; r < count; ++r) {
        std::uint64_t packets = first[r];
        for (const PendingLeaf& leaf : run_leaves(r)) {
            packets += leaf_packet_count(refs_of(refs, leaf));
        }
        if (packets >= kLeafBit) {
            throw Error("the BVH cannot hold more than 2^31 triangle packets (8.6e9 triangles)");
        }
        first[r + 1] = static_cast<std::uint32_t>(packets);
    }
    reserve_huge(tree.packets, first[count]);
    tree.packets.resize(first[count]);
    share_out(count, static_cast<int>(threads),
              [&](std::size_t r, int) { fill_run(scene, refs, run_leaves(r), first[r], tree); });
}

}  // namespace rt::bvh
