#include "rt/accel/bvh/bvh_builder.h"

#include <algorithm>
#include <array>
#include <deque>
#include <exception>
#include <future>
#include <memory>
#include <thread>
#include <utility>

#include "rt/accel/bvh/leaf_filling.h"
#include "rt/accel/bvh/sah_split.h"
#include "rt/accel/largest_first_queue.h"
#include "rt/accel/parallel_parts.h"
#include "rt/core/error.h"
#include "rt/core/huge_pages.h"

namespace rt::bvh {

namespace {

// Past this many 4-wide levels every split is an object median (which halves): the depth, and
// so the traversal stack, stays below kMaxDepth + 16 for any 2^32 references.
constexpr int kMedianDepth = 40;
// Subtrees at least this big may be built on their own thread (spawn_limit).
constexpr std::uint32_t kParallelSize = 4096;
// The two sides of a split the top builder makes are split at once when both have at least this
// many.
constexpr std::uint32_t kParallelSplit = 1u << 16;

// The top builder builds every node of more than this many references itself, and queues each
// child under it (of kParallelSize or more) for the build threads: about four a build thread, by
// size rather than by depth. By depth, one level on two threads, a sphere standing on a floor
// (`rt --model`) split into subtrees of 35k, 108k, 204k and 650k references, and the last ran
// alone for half the build. Each spawned subtree's nodes are copied once, into the top builder's.
std::uint32_t spawn_limit(std::uint32_t references, unsigned threads) {
    return std::max(kParallelSize, references / (4 * threads));
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

// One subtree's nodes and the leaves it found (packets come after, in leaf_filling.cpp), in room
// from Allocator: the whole tree's in whole huge pages (UnwrittenAllocator), a spawned subtree's
// from std::allocator. There are a few dozen of those, short-lived and about 1 MiB each: a huge
// page each would zero up to twice the memory they need.
template <template <class> class Allocator>
struct Subtree {
    std::vector<Node, Allocator<Node>> nodes;
    std::vector<PendingLeaf, Allocator<PendingLeaf>> leaves;
};

// Builds one subtree into its own arrays; a parent builder appends them to its own.
template <template <class> class Allocator>
class SubtreeBuilder {
public:
    /// `references`: how many the subtree holds, to reserve room for its nodes and leaves.
    /// `top`: the builder of the whole tree, which spawns subtrees (spawn_limit) when `threads` is
    /// more than one; the spawned ones build theirs alone.
    SubtreeBuilder(const Scene& scene, std::span<PolygonReference> refs, unsigned threads,
                   std::uint32_t references, bool top)
        : scene_(scene),
          refs_(refs),
          threads_(threads),
          spawn_limit_(top && threads > 1 ? spawn_limit(references, threads) : 0) {
        reserve_huge(nodes_, expected_nodes(references));
        reserve_huge(leaves_, expected_leaves(references));
        if (spawn_limit_ != 0) {
            // The calling thread joins them once the top is built (take_in_spawned).
            queue_ = std::make_unique<LargestFirstQueue>(threads - 1);
        }
    }

    /// The child word for `p` (an inner node's index is local to this builder).
    std::uint32_t build(Pending p, int depth);

    /// Builds the queued subtrees with the other threads, and moves them in: their nodes after
    /// this builder's, their leaves where a one-thread build finds them.
    void take_in_spawned();

    /// The nodes, and the leaves in the order a one-thread build finds them: each node's leaf
    /// children (in slot order), then its inner children's leaves, depth first. The packets are
    /// written in this order, so the tree does not depend on the thread count.
    Subtree<Allocator> take() { return {std::move(nodes_), std::move(leaves_)}; }

private:
    Pending pending(const ReferenceRange& r, int depth) {
        return {r, split_range(refs_, r, depth >= kMedianDepth, threads_)};
    }
    std::pair<Pending, Pending> pending_pair(const SplitDecision& split, int depth);
    // Until its packets are written (fill_leaves, through the leaf's node and slot), a leaf's
    // child word holds the leaf bit and the leaf's index in this builder's leaves_.
    std::uint32_t leaf(const ReferenceRange& r, std::uint32_t node, int slot) {
        if (leaves_.size() >= kLeafBit) {
            throw Error("the BVH cannot hold more than 2^31 leaves");
        }
        const auto index = static_cast<std::uint32_t>(leaves_.size());
        leaves_.push_back({node, static_cast<std::uint32_t>(slot), r.begin, r.end});
        return kLeafBit | index;
    }
    void fill(std::uint32_t index, Pending p, int depth);
    void copy_nodes(std::span<const Node> nodes, std::uint32_t node_offset);
    int open_up_to_four(Pending p, int depth, std::array<Pending, 4>& children);

    const Scene& scene_;
    std::span<PolygonReference> refs_;
    unsigned threads_;  ///< more than one: bin big ranges in parallel
    /// Children smaller than this (and of kParallelSize or more) are queued for the build
    /// threads; 0: none.
    std::uint32_t spawn_limit_;
    std::vector<Node, Allocator<Node>> nodes_;
    std::vector<PendingLeaf, Allocator<PendingLeaf>> leaves_;
    /// Queued subtrees, in the order queued, and the child word each is to fill. (A deque: the
    /// jobs write into their entries while more are added.)
    struct Spawned {
        std::uint32_t node = 0;
        int slot = 0;
        Subtree<std::allocator> subtree;
        std::exception_ptr error;
        /// How many of this builder's leaves a one-thread build would have found before this
        /// subtree's: where its leaves go (take_in_spawned).
        std::size_t leaves_before = 0;
    };
    std::deque<Spawned> spawned_;
    /// spawned_'s indices in the order a one-thread build would have built them.
    std::vector<std::size_t> spawned_in_tree_order_;
    /// Declared last, so destroyed first: its threads write into spawned_.
    std::unique_ptr<LargestFirstQueue> queue_;
};

// Replaces the largest splittable range by its halves until there are four (or none left).
template <template <class> class Allocator>
int SubtreeBuilder<Allocator>::open_up_to_four(Pending p, int depth,
                                               std::array<Pending, 4>& children) {
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

// The two sides of a split, each with its own split decided. In the top builder, whose nodes no
// other thread builds, the two are split at once on two threads (each binning on half of the
// build's threads): otherwise the first levels were split on one thread while the others waited.
// The decisions do not depend on the threads (split_range).
template <template <class> class Allocator>
std::pair<Pending, Pending> SubtreeBuilder<Allocator>::pending_pair(const SplitDecision& split,
                                                                    int depth) {
    if (spawn_limit_ != 0 && std::min(split.left.size(), split.right.size()) >= kParallelSplit) {
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

template <template <class> class Allocator>
std::uint32_t SubtreeBuilder<Allocator>::build(Pending p, int depth) {
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
template <template <class> class Allocator>
void SubtreeBuilder<Allocator>::fill(std::uint32_t index, Pending p, int depth) {
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
    // Each inner child is either built here or spawned; spawned_as tells which.
    constexpr std::size_t kBuiltHere = ~std::size_t{0};
    std::array<std::size_t, 4> spawned_as{kBuiltHere, kBuiltHere, kBuiltHere, kBuiltHere};
    for (int c = 0; c < count; ++c) {
        const Pending& child = children[c];
        if (child.split.leaf) {
            nodes_[index].child[c] = leaf(child.range, index, c);
        } else if (child.range.size() < spawn_limit_ && child.range.size() >= kParallelSize) {
            spawned_as[c] = spawned_.size();
            Spawned& spawned = spawned_.emplace_back(Spawned{index, c, {}, {}});
            queue_->push(child.range.size(), [this, child, depth, &spawned] {
                try {
                    SubtreeBuilder<std::allocator> sub(scene_, refs_, threads_, child.range.size(),
                                                       false);
                    sub.build(child, depth + 1);
                    spawned.subtree = sub.take();
                } catch (...) {
                    spawned.error = std::current_exception();
                }
            });
        } else {
            nodes_[index].child[c] = static_cast<std::uint32_t>(nodes_.size());
            nodes_.emplace_back();
        }
    }
    // The spawned subtrees are waited for only when the whole top is built: waiting for each in
    // turn here held back the spawning of the next node's children. A one-thread build would
    // build them here, in turn with the others.
    for (int c = 0; c < count; ++c) {
        if (children[c].split.leaf) {
            continue;
        }
        if (spawned_as[c] == kBuiltHere) {
            fill(nodes_[index].child[c], children[c], depth + 1);
        } else {
            spawned_[spawned_as[c]].leaves_before = leaves_.size();
            spawned_in_tree_order_.push_back(spawned_as[c]);
        }
    }
}

template <template <class> class Allocator>
void SubtreeBuilder<Allocator>::take_in_spawned() {
    if (spawned_.empty()) {
        return;
    }
    queue_->finish();
    std::size_t total_nodes = nodes_.size();
    std::size_t total_leaves = leaves_.size();
    for (const Spawned& s : spawned_) {
        if (s.error) {
            std::rethrow_exception(s.error);
        }
        total_nodes += s.subtree.nodes.size();
        total_leaves += s.subtree.leaves.size();
    }
    if (total_leaves > kLeafBit) {
        throw Error("the BVH cannot hold more than 2^31 leaves");
    }
    // Where each subtree goes: its nodes after this builder's and the subtrees' before it in tree
    // order; its leaves, already in its own one-thread order, as a block where a one-thread build
    // would have found them among this builder's, which go just ahead of it.
    struct Placement {
        Spawned* subtree;
        std::uint32_t node_offset;
        std::size_t own_from, own_to;  ///< this builder's leaves that go just ahead of it
        std::size_t leaf_at;           ///< where those go; the subtree's follow them
    };
    std::vector<Placement> plan;
    plan.reserve(spawned_in_tree_order_.size());
    auto node_offset = static_cast<std::uint32_t>(nodes_.size());
    std::size_t leaf_at = 0;
    std::size_t taken = 0;
    for (const std::size_t i : spawned_in_tree_order_) {
        Spawned& s = spawned_[i];
        plan.push_back({&s, node_offset, taken, s.leaves_before, leaf_at});
        node_offset += static_cast<std::uint32_t>(s.subtree.nodes.size());
        leaf_at += s.leaves_before - taken + s.subtree.leaves.size();
        taken = s.leaves_before;
    }
    // Sized without being written (UnwrittenAllocator), then copied into by every build thread, so
    // that each faults in its own part of the fresh memory: a fresh page's first touch can cost
    // far more than the copy (docs/accelerators.md, "Build speed").
    nodes_.resize(total_nodes);
    std::vector<PendingLeaf, Allocator<PendingLeaf>> leaves;
    reserve_huge(leaves, total_leaves);
    leaves.resize(total_leaves);
    const auto copy_own = [&](std::size_t from, std::size_t to, std::size_t at) {
        std::copy(leaves_.begin() + static_cast<std::ptrdiff_t>(from),
                  leaves_.begin() + static_cast<std::ptrdiff_t>(to),
                  leaves.begin() + static_cast<std::ptrdiff_t>(at));
    };
    // A subtree at a time to each thread as it comes free: their sizes differ, and a core slowed
    // by another program holds no other back.
    share_out(plan.size(), static_cast<int>(threads_), [&](std::size_t i, int) {
        const Placement& p = plan[i];
        Subtree<std::allocator>& sub = p.subtree->subtree;
        copy_own(p.own_from, p.own_to, p.leaf_at);
        copy_nodes(sub.nodes, p.node_offset);
        auto out = leaves.begin() + static_cast<std::ptrdiff_t>(p.leaf_at + p.own_to - p.own_from);
        for (PendingLeaf leaf : sub.leaves) {
            leaf.node += p.node_offset;  // a spawned subtree's root is never a leaf
            *out++ = leaf;
        }
        sub = {};
    });
    copy_own(taken, leaves_.size(), leaf_at);
    for (const Placement& p : plan) {
        nodes_[p.subtree->node].child[p.subtree->slot] = p.node_offset;  // the subtree's node 0
    }
    leaves_ = std::move(leaves);
    spawned_.clear();
    spawned_in_tree_order_.clear();
}

// Copies a finished subtree's nodes to `node_offset` on, shifting their node indices. Their
// leaves' child words are left as they are: the packets' indices replace them (fill_leaves).
template <template <class> class Allocator>
void SubtreeBuilder<Allocator>::copy_nodes(std::span<const Node> nodes, std::uint32_t node_offset) {
    auto out = nodes_.begin() + static_cast<std::ptrdiff_t>(node_offset);
    for (Node node : nodes) {
        for (std::uint32_t& child : node.child) {
            if (child != kNoChild && !is_leaf(child)) {
                child += node_offset;
            }
        }
        *out++ = node;
    }
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
    SubtreeBuilder<UnwrittenAllocator> builder(scene, all, threads,
                                               static_cast<std::uint32_t>(all.size()), true);
    const ReferenceRange whole = make_range(all, 0, static_cast<std::uint32_t>(all.size()));
    result.root = builder.build({whole, split_range(all, whole, false, threads)}, 0);
    builder.take_in_spawned();
    Subtree<UnwrittenAllocator> tree = builder.take();
    result.nodes = std::move(tree.nodes);
    fill_leaves(scene, all, tree.leaves, result, threads);
    // The nodes keep their reserved room: collapse_to_wide frees them soon after, and shrinking
    // them copied them into fresh memory. The packets were sized exactly (fill_leaves).
    return result;
}

}  // namespace rt::bvh
