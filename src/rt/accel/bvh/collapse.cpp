// Each wide node takes a 4-wide node's children and, while they fit in eight slots, replaces the
// inner child of largest box surface by that child's own children (as Embree's collapse does).
#include "rt/accel/bvh/collapse.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

#include "rt/accel/parallel_parts.h"
#include "rt/core/error.h"
#include "rt/core/huge_pages.h"

namespace rt::bvh {

namespace {

struct Slot {
    std::uint32_t child;
    float lo[3];
    float hi[3];
    double half_area() const {
        const double x = static_cast<double>(hi[0]) - lo[0];
        const double y = static_cast<double>(hi[1]) - lo[1];
        const double z = static_cast<double>(hi[2]) - lo[2];
        return x * y + y * z + z * x;
    }
};

int children_of(const Node& node, Slot* out) {
    int count = 0;
    for (int c = 0; c < 4; ++c) {
        if (node.child[c] == kNoChild) {
            continue;
        }
        Slot& s = out[count++];
        s.child = node.child[c];
        for (int k = 0; k < 3; ++k) {
            s.lo[k] = node.lo[k][c];
            s.hi[k] = node.hi[k][c];
        }
    }
    return count;
}

// The wide node's children for 4-wide node `node_index`: its children, with the inner child of
// largest box surface replaced by that child's children while they fit in eight.
int wide_children(const Hierarchy& tree, std::uint32_t node_index, Slot* slots) {
    int count = children_of(tree.nodes[node_index], slots);
    for (;;) {
        int best = -1;
        double best_area = -1.0;
        for (int i = 0; i < count; ++i) {
            if (is_leaf(slots[i].child)) {
                continue;
            }
            Slot grand[4];
            const int n = children_of(tree.nodes[slots[i].child], grand);
            if (count - 1 + n <= 8 && slots[i].half_area() > best_area) {
                best = i;
                best_area = slots[i].half_area();
            }
        }
        if (best < 0) {
            break;
        }
        Slot grand[4];
        const int n = children_of(tree.nodes[slots[best].child], grand);
        slots[best] = grand[0];
        for (int g = 1; g < n; ++g) {
            slots[count++] = grand[g];
        }
    }
    return count;
}

// How many wide nodes collapse makes for the subtree of `node_index`.
std::size_t count_wide(const Hierarchy& tree, std::uint32_t node_index) {
    Slot slots[8];
    const int count = wide_children(tree, node_index, slots);
    std::size_t total = 1;
    for (int c = 0; c < count; ++c) {
        if (!is_leaf(slots[c].child)) {
            total += count_wide(tree, slots[c].child);
        }
    }
    return total;
}

// Writes the wide node of `slots` to `out`, each inner child's word from child(slot).
template <class PlaceChild>
void write_wide_node(const Slot* slots, int count, WideNode& out, PlaceChild&& child) {
    WideNode result{};  // its padding too is zero, so equal trees have equal bytes
    for (int c = 0; c < 8; ++c) {
        result.child[c] = kNoChild;
        for (int k = 0; k < 3; ++k) {
            result.lo[k][c] = HUGE_VALF;
            result.hi[k][c] = -HUGE_VALF;
        }
    }
    for (int c = 0; c < count; ++c) {
        for (int k = 0; k < 3; ++k) {
            result.lo[k][c] = slots[c].lo[k];
            result.hi[k][c] = slots[c].hi[k];
        }
        result.child[c] = is_leaf(slots[c].child) ? slots[c].child : child(slots[c]);
    }
    std::memcpy(&out, &result, sizeof(WideNode));  // the room was never written
}

// The top of the wide tree, this many levels deep, is laid out on one thread; the subtrees below
// it (up to 8^3, usually a few hundred) are counted and written by every thread.
constexpr int kTopLevels = 3;
// Below this many 4-wide nodes, one thread collapses faster than several start.
constexpr std::size_t kNodesForThreads = 4096;

struct Part {
    std::uint32_t node;   ///< the 4-wide node at its root
    std::size_t size;     ///< its wide nodes
    std::uint32_t first;  ///< where they start in tree.wide
};

// Appends the subtrees `levels` wide levels below `node_index` (where lay_out puts parts), in
// preorder; returns how many wide nodes lie above them.
std::size_t find_parts(const Hierarchy& tree, std::uint32_t node_index, int levels,
                       std::vector<Part>& parts) {
    if (levels == 0) {
        parts.push_back({node_index, 0, 0});
        return 0;
    }
    Slot slots[8];
    const int count = wide_children(tree, node_index, slots);
    std::size_t top = 1;
    for (int c = 0; c < count; ++c) {
        if (!is_leaf(slots[c].child)) {
            top += find_parts(tree, slots[c].child, levels - 1, parts);
        }
    }
    return top;
}

// Writes the wide nodes of the subtree of `node_index` from wide[next] on, in preorder (a node,
// then each inner child's subtree in slot order), and returns its root's index. Subtrees `levels`
// wide levels down (none if `levels` is negative) are not written but given their place: each is
// the next of the parts at `part`, whose sizes are counted.
std::uint32_t lay_out(const Hierarchy& tree, std::uint32_t node_index, int levels, WideNode* wide,
                      std::uint32_t& next, Part*& part) {
    if (levels == 0) {
        part->first = next;
        next += static_cast<std::uint32_t>(part->size);
        return (part++)->first;
    }
    Slot slots[8];
    const int count = wide_children(tree, node_index, slots);
    const std::uint32_t index = next++;
    write_wide_node(slots, count, wide[index], [&](const Slot& slot) {
        return lay_out(tree, slot.child, levels - 1, wide, next, part);
    });
    return index;
}

}  // namespace

void collapse_to_wide(Hierarchy& tree, unsigned threads) {
    if (tree.root != kNoChild && !is_leaf(tree.root)) {
        if (threads == 0) {
            threads = std::max(1u, std::thread::hardware_concurrency());
        }
        if (tree.nodes.size() < kNodesForThreads) {
            threads = 1;
        }
        // Counted first, so that the array is written once, in room of its exact size: a guess
        // that was too big was copied into a fitting array after, and on a first build every
        // page of each array is a page fault (665 of them on the 100k sphere, 7 of its 8 ms).
        // The top's few nodes are laid out on one thread, the parts below it counted and written
        // by all, each in its own place, so the tree is the same for any thread count.
        std::vector<Part> parts;
        std::size_t total = find_parts(tree, tree.root, kTopLevels, parts);
        share_out(parts.size(), static_cast<int>(threads),
                  [&](std::size_t i, int) { parts[i].size = count_wide(tree, parts[i].node); });
        for (const Part& part : parts) {
            total += part.size;
        }
        if (total >= kLeafBit) {
            throw Error("the BVH cannot hold more than 2^31 wide nodes");
        }
        reserve_huge(tree.wide, total);
        tree.wide.resize(total);  // written below: the array leaves its elements unwritten
        std::uint32_t next = 0;
        Part* part = parts.data();
        tree.root = lay_out(tree, tree.root, kTopLevels, tree.wide.data(), next, part);
        share_out(parts.size(), static_cast<int>(threads), [&](std::size_t i, int) {
            std::uint32_t at = parts[i].first;
            Part* none = nullptr;
            lay_out(tree, parts[i].node, -1, tree.wide.data(), at, none);
        });
    }
    tree.nodes.clear();
    tree.nodes.shrink_to_fit();
}

}  // namespace rt::bvh
