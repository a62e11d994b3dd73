#include "rt/accel/bvh/leaf_filling.h"

#include <algorithm>
#include <thread>

#include "rt/accel/bvh/leaf_packets.h"
#include "rt/core/huge_pages.h"

namespace rt::bvh {

namespace {

// How many leaves ahead each link of the chain is asked for: the polygon records first, their
// corner lists once the records have had time to arrive, the positions last.
constexpr std::size_t kRecordsAhead = 12;
constexpr std::size_t kCornersAhead = 6;
constexpr std::size_t kPositionsAhead = 2;

struct Run {
    std::vector<TrianglePacket> packets;
    std::vector<std::uint32_t> first;  ///< each leaf's first packet, within `packets`
};

std::span<const PolygonReference> refs_of(std::span<const PolygonReference> refs,
                                          const PendingLeaf& leaf) {
    return refs.subspan(leaf.begin, leaf.end - leaf.begin);
}

// Four fan triangles a packet, each leaf's own: what append_leaf_packets makes today, used only
// to reserve memory (a wrong guess costs a copy, not an error).
std::size_t expected_packets(std::span<const PolygonReference> refs,
                             std::span<const PendingLeaf> leaves) {
    std::size_t packets = 0;
    for (const PendingLeaf& leaf : leaves) {
        std::size_t triangles = 0;
        for (const PolygonReference& ref : refs_of(refs, leaf)) {
            triangles += ref.triangles;
        }
        packets += (triangles + 3) / 4;
    }
    return packets;
}

void fill_run(const Scene& scene, std::span<const PolygonReference> refs,
              std::span<const PendingLeaf> leaves, std::size_t reserve, Run& run) {
    reserve_huge(run.packets, reserve);
    run.first.reserve(leaves.size());
    const auto ahead = [&](std::size_t i, auto&& ask) {
        if (i < leaves.size()) {
            for (const PolygonReference& ref : refs_of(refs, leaves[i])) {
                ask(scene.polygons[ref.polygon]);
            }
        }
    };
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        ahead(i + kRecordsAhead, [](const Polygon& p) { __builtin_prefetch(&p); });
        ahead(i + kCornersAhead,
              [&](const Polygon& p) { __builtin_prefetch(scene.corners.data() + p.first_corner); });
        ahead(i + kPositionsAhead, [&](const Polygon& p) {
            for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                __builtin_prefetch(&scene.positions[scene.corners[p.first_corner + k]]);
            }
        });
        run.first.push_back(append_leaf_packets(scene, refs_of(refs, leaves[i]), run.packets));
    }
}

void point_at(Hierarchy& tree, const PendingLeaf& leaf, std::uint32_t packet) {
    std::uint32_t& word =
        leaf.node == kNoChild ? tree.root : tree.nodes[leaf.node].child[leaf.slot];
    word = kLeafBit | packet;
}

}  // namespace

void fill_leaves(const Scene& scene, std::span<const PolygonReference> refs,
                 std::span<const PendingLeaf> leaves, Hierarchy& tree, unsigned threads) {
    // Runs of whole leaves, in the order given, about as many references each.
    const std::size_t count =
        std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(leaves.size() / 4096, 1));
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
    std::vector<Run> runs(count);
    std::vector<std::thread> pool;
    for (std::size_t r = 1; r < count; ++r) {
        pool.emplace_back([&, r] {
            fill_run(scene, refs, run_leaves(r), expected_packets(refs, run_leaves(r)), runs[r]);
        });
    }
    // The first run's packets become the tree's: room for every run's.
    fill_run(scene, refs, run_leaves(0), expected_packets(refs, leaves), runs[0]);
    for (std::thread& t : pool) {
        t.join();
    }
    std::size_t total = 0;
    for (const Run& run : runs) {
        total += run.packets.size();
    }
    tree.packets = std::move(runs[0].packets);
    reserve_huge(tree.packets, total);
    for (std::size_t r = 0; r < count; ++r) {
        const auto offset = static_cast<std::uint32_t>(r == 0 ? 0 : tree.packets.size());
        if (r > 0) {
            tree.packets.insert(tree.packets.end(), runs[r].packets.begin(), runs[r].packets.end());
            runs[r].packets = {};
        }
        for (std::size_t i = bounds[r]; i < bounds[r + 1]; ++i) {
            point_at(tree, leaves[i], offset + runs[r].first[i - bounds[r]]);
        }
    }
}

}  // namespace rt::bvh
