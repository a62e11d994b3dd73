// Each wide node takes a 4-wide node's children and, while they fit in eight slots, replaces the
// inner child of largest box surface by that child's own children (as Embree's collapse does).
#include "rt/accel/bvh/collapse.h"

#include <cmath>

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

std::uint32_t collapse(const Hierarchy& tree, std::uint32_t node_index, WideNodeArray& wide) {
    Slot slots[8];
    const int count = wide_children(tree, node_index, slots);
    const auto index = static_cast<std::uint32_t>(wide.size());
    wide.emplace_back();
    WideNode result{};
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
        result.child[c] =
            is_leaf(slots[c].child) ? slots[c].child : collapse(tree, slots[c].child, wide);
    }
    wide[index] = result;
    return index;
}

}  // namespace

void collapse_to_wide(Hierarchy& tree) {
    if (tree.root != kNoChild && !is_leaf(tree.root)) {
        // Counted first, so that the array is written once, in room of its exact size: a guess
        // that was too big was copied into a fitting array after, and on a first build every
        // page of each array is a page fault (665 of them on the 100k sphere, 7 of its 8 ms).
        // Counting reads the nodes once more, from the caches: under 0.5 ms there.
        reserve_huge(tree.wide, count_wide(tree, tree.root));
        tree.root = collapse(tree, tree.root, tree.wide);
    }
    tree.nodes.clear();
    tree.nodes.shrink_to_fit();
}

}  // namespace rt::bvh
