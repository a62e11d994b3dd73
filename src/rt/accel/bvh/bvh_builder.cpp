#include "rt/accel/bvh/bvh_builder.h"

#include <algorithm>
#include <array>
#include <future>
#include <thread>
#include <utility>

#include "rt/accel/bvh/leaf_filling.h"
#include "rt/accel/bvh/sah_split.h"
#include "rt/core/huge_pages.h"

namespace rt::bvh {

namespace {

// Past this many 4-wide levels every split is an object median (which halves): the depth, and
// so the traversal stack, stays below kMaxDepth + 16 for any 2^32 references.
constexpr int kMedianDepth = 40;
// Subtrees at least this big, and shallow enough (spawn_depth), are built on their own thread.
constexpr std::uint32_t kParallelSize = 4096;
// The two sides of a split near the top are split at once when both have at least this many.
constexpr std::uint32_t kParallelSplit = 1u << 16;

// Subtrees above this depth get their own threads: enough of them (four a level) for two a
// thread, and no more. Each spawned subtree's nodes are copied into its parent's, a copy a level,
// and a small subtree's arrays are too small for huge pages, so each extra level costs fresh
// memory, page fault by page fault (docs/lab/bvh-first-build-2026-12-03.md).
int spawn_depth(unsigned threads) {
    int depth = 1;
    while (depth < 3 && (1u << (2 * depth)) < 2 * threads) {
        ++depth;
    }
    return depth;
}

// Generous guesses of a subtree's nodes and leaves (the 1M sphere and soup have one node per 12
// references and one leaf per 4), reserved before the build so that the arrays never move while
// they grow: on a first build each move copied into fresh memory, page fault by page fault. A
// wrong guess costs a copy, not an error; room reserved and never written costs no memory.
std::size_t expected_nodes(std::uint32_t references) {
    return references / 6 + 16;
}
std::size_t expected_leaves(std::uint32_t references) {
    return references / 2 + 16;
}

struct Pending {
    ReferenceRange range;
    SplitDecision split;
};

// One subtree's nodes and the leaves it found (packets come after, in leaf_filling.cpp).
struct Subtree {
    std::vector<Node> nodes;
    std::vector<PendingLeaf> leaves;
};

// Builds one subtree into its own arrays; a parent builder appends them to its own.
class SubtreeBuilder {
public:
    /// `references`: how many the subtree holds, to reserve room for its nodes and leaves.
    SubtreeBuilder(const Scene& scene, std::span<PolygonReference> refs, unsigned threads,
                   std::uint32_t references)
        : scene_(scene), refs_(refs), threads_(threads), spawn_depth_(spawn_depth(threads)) {
        reserve_huge(nodes_, expected_nodes(references));
        reserve_huge(leaves_, expected_leaves(references));
    }

    /// The child word for `p` (an inner node's index is local to this builder).
    std::uint32_t build(Pending p, int depth);

    Subtree take() { return {std::move(nodes_), std::move(leaves_)}; }

private:
    Pending pending(const ReferenceRange& r, int depth) {
        return {r, split_range(refs_, r, depth >= kMedianDepth, threads_)};
    }
    std::pair<Pending, Pending> pending_pair(const SplitDecision& split, int depth);
    // A leaf's child word is written once its packets are (fill_leaves).
    std::uint32_t leaf(const ReferenceRange& r, std::uint32_t node, int slot) {
        leaves_.push_back({node, static_cast<std::uint32_t>(slot), r.begin, r.end});
        return kLeafBit;
    }
    void fill(std::uint32_t index, Pending p, int depth);
    std::uint32_t append(Subtree&& sub);
    int open_up_to_four(Pending p, int depth, std::array<Pending, 4>& children);

    const Scene& scene_;
    std::span<PolygonReference> refs_;
    unsigned threads_;  ///< more than one: spawn subtrees, bin big ranges in parallel
    int spawn_depth_;
    std::vector<Node> nodes_;
    std::vector<PendingLeaf> leaves_;
};

// Replaces the largest splittable range by its halves until there are four (or none left).
int SubtreeBuilder::open_up_to_four(Pending p, int depth, std::array<Pending, 4>& children) {
    children[0] = p;
    int count = 1;
    while (count < 4) {
        int widest = -1;
        double widest_area = -1.0;
        for (int i = 0; i < count; ++i) {
            const double area = children[i].range.box.half_area();
            if (!children[i].split.leaf && area > widest_area) {
                widest = i;
                widest_area = area;
            }
        }
        if (widest < 0) {
            break;
        }
        const SplitDecision split = children[widest].split;
        const auto [left, right] = pending_pair(split, depth);
        children[widest] = left;
        children[count++] = right;
    }
    return count;
}

// The two sides of a split, each with its own split decided. Near the top, where the subtrees
// have no threads of their own yet, the two are split at once on two threads (each binning on
// half of the build's threads): otherwise the first levels were split on one thread while the
// others waited. The decisions do not depend on the threads (split_range).
std::pair<Pending, Pending> SubtreeBuilder::pending_pair(const SplitDecision& split, int depth) {
    if (threads_ > 1 && depth <= spawn_depth_ &&
        std::min(split.left.size(), split.right.size()) >= kParallelSplit) {
        const unsigned left_threads = threads_ / 2;
        const bool by_median = depth >= kMedianDepth;
        std::future<SplitDecision> right = std::async(std::launch::async, [&] {
            return split_range(refs_, split.right, by_median, threads_ - left_threads);
        });
        Pending left{split.left, split_range(refs_, split.left, by_median, left_threads)};
        return {left, {split.right, right.get()}};
    }
    return {pending(split.left, depth), pending(split.right, depth)};
}

std::uint32_t SubtreeBuilder::build(Pending p, int depth) {
    if (p.split.leaf) {
        return leaf(p.range, kNoChild, 0);
    }
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    fill(index, p, depth);
    return index;
}

// Fills node `index` with up to four children. The inner children built here get consecutive
// nodes, and the leaves consecutive packets, so that a ray testing siblings reads neighbouring
// cache lines.
void SubtreeBuilder::fill(std::uint32_t index, Pending p, int depth) {
    std::array<Pending, 4> children;
    const int count = open_up_to_four(p, depth + 1, children);
    for (int c = 0; c < 4; ++c) {
        Node& node = nodes_[index];
        const Box box = c < count ? children[c].range.box : Box{};
        for (int k = 0; k < 3; ++k) {
            node.lo[k][c] = box.lo[k];
            node.hi[k][c] = box.hi[k];
        }
        node.child[c] = kNoChild;
    }
    std::vector<std::pair<int, std::future<Subtree>>> spawned;
    std::array<bool, 4> built_here{};
    for (int c = 0; c < count; ++c) {
        const Pending& child = children[c];
        if (child.split.leaf) {
            nodes_[index].child[c] = leaf(child.range, index, c);
        } else if (threads_ > 1 && depth < spawn_depth_ && child.range.size() >= kParallelSize) {
            spawned.emplace_back(c, std::async(std::launch::async, [this, child, depth] {
                                     SubtreeBuilder sub(scene_, refs_, threads_,
                                                        child.range.size());
                                     sub.build(child, depth + 1);
                                     return sub.take();
                                 }));
        } else {
            built_here[c] = true;
            nodes_[index].child[c] = static_cast<std::uint32_t>(nodes_.size());
            nodes_.emplace_back();
        }
    }
    for (int c = 0; c < count; ++c) {
        if (built_here[c]) {
            fill(nodes_[index].child[c], children[c], depth + 1);
        }
    }
    for (auto& [c, future] : spawned) {
        nodes_[index].child[c] = append(future.get());
    }
}

// Moves a finished subtree in, shifting its node indices; returns its root's index.
std::uint32_t SubtreeBuilder::append(Subtree&& sub) {
    const auto node_offset = static_cast<std::uint32_t>(nodes_.size());
    for (Node& node : sub.nodes) {
        for (std::uint32_t& child : node.child) {
            if (child != kNoChild && !is_leaf(child)) {
                child += node_offset;
            }
        }
    }
    nodes_.insert(nodes_.end(), sub.nodes.begin(), sub.nodes.end());
    for (PendingLeaf& leaf : sub.leaves) {
        leaf.node += node_offset;  // a spawned subtree's root is never a leaf
    }
    leaves_.insert(leaves_.end(), sub.leaves.begin(), sub.leaves.end());
    return node_offset;  // the subtree's root is its node 0
}

}  // namespace

Hierarchy build_hierarchy(const Scene& scene, PolygonReferences& refs, unsigned threads) {
    if (threads == 0) {
        threads = std::max(1u, std::thread::hardware_concurrency());
    }
    Hierarchy result;
    result.scale = refs.scale;
    if (refs.bounded.empty()) {
        return result;
    }
    const std::span<PolygonReference> all(refs.bounded);
    SubtreeBuilder builder(scene, all, threads, static_cast<std::uint32_t>(all.size()));
    const ReferenceRange whole = make_range(all, 0, static_cast<std::uint32_t>(all.size()));
    result.root = builder.build({whole, split_range(all, whole, false, threads)}, 0);
    Subtree tree = builder.take();
    result.nodes = std::move(tree.nodes);
    fill_leaves(scene, all, tree.leaves, result, threads);
    // The nodes keep their reserved room: collapse_to_wide frees them soon after, and shrinking
    // them copied them into fresh memory. The packets were sized exactly (fill_leaves).
    return result;
}

}  // namespace rt::bvh
