// The DDDA (manual 1.3: "the ray is traced using an integer DDDA algorithm similar to the DDA
// algorithm used in drawing lines"): the walk from leaf to leaf along the ray. The position is
// kept as integer coordinates on the finest lattice (2^depth a side); the leaf holding it is
// found by reading those coordinates' bits (OctreeCursor); the ray leaves that leaf through
// the nearest of its three far faces, whose lattice planes are integers too, so the next
// position is an integer step across that face (the other two coordinates are read from where
// the ray crosses it, kept within the face). Only the crossing t is floating point, and it is
// computed afresh from the lattice each time, so no error builds up along a long walk.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>

#include "rt/accel/octree/octree_top_table.h"
#include "rt/accel/octree/octree_tree.h"
#include "rt/core/prefetch.h"

namespace rt {

/// The leaf containing lattice point `at`, with its lowest lattice corner and side.
struct OctreeLeafAt {
    const OctreeNode* node = nullptr;
    std::int64_t origin[3] = {0, 0, 0};
    std::int64_t size = 1;
};

/// The path from the root to the leaf holding a lattice point. Moving to the next point climbs
/// only as far as the lowest ancestor holding both points (the highest bit in which their
/// coordinates differ says which) and descends from there, so a step between neighbouring leaves
/// costs a level or two instead of a walk from the root.
class OctreeCursor {
public:
    OctreeCursor(const OctreeTree& tree, const std::int64_t at[3])
        : OctreeCursor(tree.nodes.data(), tree.depth, at) {}

    /// The same over `nodes`: the tree's own, or an array of the same shape (octree.h); with
    /// `top` (made for the same tree; null: none), descents that would start above its level
    /// start from it.
    // path_ is left uninitialised on purpose (see its comment).
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-member-init)
    OctreeCursor(const OctreeNode* nodes, int depth, const std::int64_t at[3],
                 const OctreeTopTable* top = nullptr)
        : nodes_(nodes), depth_(depth), top_(top != nullptr && top->level > 0 ? top : nullptr) {
        path_[0] = nodes;
        for (int a = 0; a < 3; ++a) {
            at_[a] = at[a];
        }
        if (top_ != nullptr) {
            from_table();
        }
        descend();
    }

    void move_to(const std::int64_t next[3]) {
        std::uint64_t differ = 0;
        for (int a = 0; a < 3; ++a) {
            differ |= static_cast<std::uint64_t>(next[a] ^ at_[a]);
            at_[a] = next[a];
        }
        const int common = depth_ - static_cast<int>(std::bit_width(differ));
        if (top_ != nullptr && common < top_->level) {
            from_table();
        } else {
            level_ = std::min(level_, common);
        }
        descend();
    }

    /// The leaf holding the current point.
    const OctreeNode* leaf_node() const { return path_[level_]; }

    OctreeLeafAt leaf() const {
        OctreeLeafAt leaf;
        leaf.node = path_[level_];
        leaf.size = std::int64_t{1} << (depth_ - level_);
        for (int a = 0; a < 3; ++a) {
            leaf.origin[a] = at_[a] & ~(leaf.size - 1);
        }
        return leaf;
    }

private:
    // Starts the path at the table's entry for the current point: the levels above it are never
    // read, as any step that would climb above the table's level comes back here.
    void from_table() {
        const OctreeTopTable::Entry e = top_->at(at_, depth_);
        level_ = static_cast<int>(e.level);
        path_[level_] = nodes_ + e.node;
    }

    void descend() {
        while (!path_[level_]->is_leaf()) {
            const int shift = depth_ - 1 - level_;
            const auto child = static_cast<std::uint32_t>(((at_[0] >> shift) & 1) |
                                                          (((at_[1] >> shift) & 1) << 1) |
                                                          (((at_[2] >> shift) & 1) << 2));
            path_[level_ + 1] = nodes_ + path_[level_]->first + child;
            ++level_;
        }
    }

    const OctreeNode* nodes_;
    int depth_;
    const OctreeTopTable* top_;
    // Only levels 0 .. level_ are ever read; left uninitialised, as zeroing them all cost a
    // visible share of a short walk.
    const OctreeNode* path_[kMaxOctreeDepth + 1];
    int level_ = 0;
    std::int64_t at_[3] = {0, 0, 0};
};

/// The walk itself, for a ray already clipped to the world: `inside` is what clip_to_box gave
/// for the interval (callers that clip first skip the rest of their setup for rays that miss).
/// `nodes` is the tree's node array or one of the same shape whose leaves say where their own
/// data lies; visit(t_exit, leaf) is called for each leaf, leaf.node pointing into `nodes`.
/// `inverse[a]` is 1 / ray.direction[a] on each axis the ray moves along (what the caller's clip
/// used). With kLookAhead, `prefetch(node)` is called with each next leaf as soon as it is found,
/// before the current one is visited, to ask the cache for what its visit will read; without,
/// the next leaf is found only after the visit, and not at all when the visit ends the walk.
/// The leaves visited, in order, and where the walk ends are the same either way.
template <bool kLookAhead = true, class Visit, class Prefetch>
void walk_octree_leaves(const OctreeTree& tree, const OctreeNode* nodes, const OctreeTopTable* top,
                        const Ray& ray, const Vec3& inverse, Interval inside, Visit&& visit,
                        Prefetch&& prefetch) {
    const std::int64_t last = (std::int64_t{1} << tree.depth) - 1;
    // The lattice cell holding the point at t, clamped to [low, high] on each axis.
    // Products with reciprocals rather than divisions: the rounding differs by an ulp or so,
    // far below the fudge, and a step costs less.
    const Vec3& per_step = tree.per_step;
    auto lattice_cell = [&](int a, double at_t, std::int64_t low, std::int64_t high) {
        const double x = ray.origin[a] + at_t * ray.direction[a];
        const double c = std::floor((x - tree.world.lo[a]) * per_step[a]);
        return static_cast<std::int64_t>(
            std::clamp(c, static_cast<double>(low), static_cast<double>(high)));
    };
    std::int64_t at[3];
    int step[3];
    for (int a = 0; a < 3; ++a) {
        at[a] = lattice_cell(a, inside.min, 0, last);
        step[a] = ray.direction[a] > 0.0 ? 1 : (ray.direction[a] < 0.0 ? -1 : 0);
    }
    constexpr double kNever = std::numeric_limits<double>::infinity();
    OctreeCursor cursor(nodes, tree.depth, at, top);
    while (true) {
        const OctreeLeafAt leaf = cursor.leaf();
        double t_face[3];
        for (int a = 0; a < 3; ++a) {
            const std::int64_t plane = leaf.origin[a] + (step[a] > 0 ? leaf.size : 0);
            t_face[a] =
                step[a] == 0 ? kNever : (tree.lattice(a, plane) - ray.origin[a]) * inverse[a];
        }
        const int axis = t_face[0] < t_face[1] ? (t_face[0] < t_face[2] ? 0 : 2)
                                               : (t_face[1] < t_face[2] ? 1 : 2);
        const double t_exit = t_face[axis];
        // With kLookAhead the next leaf is found before this one's polygons are tested, and its
        // polygon list asked for, so that the memory it lives in arrives while they are being
        // tested. The leaves visited, and where the walk ends, are the same as stepping after
        // the visit.
        bool more = t_exit < inside.max;
        if constexpr (!kLookAhead) {
            if (visit(t_exit, leaf) || !more) {
                return;
            }
        }
        if (more) {
            at[axis] = step[axis] > 0 ? leaf.origin[axis] + leaf.size : leaf.origin[axis] - 1;
            more = at[axis] >= 0 && at[axis] <= last;
        }
        if (more) {
            // Within the face, and never back against the ray's direction: every coordinate
            // then only moves forward, so the walk cannot revisit a leaf whatever the rounding.
            // A leaf one lattice step wide leaves the other coordinates nowhere else to go.
            for (int a = 0; a < 3 && leaf.size > 1; ++a) {
                if (a != axis && step[a] > 0) {
                    at[a] = lattice_cell(a, t_exit, at[a], leaf.origin[a] + leaf.size - 1);
                } else if (a != axis && step[a] < 0) {
                    at[a] = lattice_cell(a, t_exit, leaf.origin[a], at[a]);
                }
            }
            cursor.move_to(at);
            if constexpr (kLookAhead) {
                prefetch(cursor.leaf_node());
            }
        }
        if constexpr (kLookAhead) {
            if (visit(t_exit, leaf) || !more) {
                return;
            }
        } else if (!more) {
            return;
        }
    }
}

/// walk_octree for a ray already clipped to the world (see walk_octree_leaves), computing the
/// reciprocals and asking the cache for each next leaf's polygon ids.
template <class Visit>
void walk_octree_inside(const OctreeTree& tree, const Ray& ray, Interval inside, Visit&& visit) {
    const Vec3 inverse{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    walk_octree_leaves(
        tree, tree.nodes.data(), nullptr, ray, inverse, inside,
        [&](double t_exit, const OctreeLeafAt& leaf) {
            return visit(tree.leaf_polygons(*leaf.node), t_exit, leaf);
        },
        [&](const OctreeNode* node) { prefetch(tree.polygons.data() + node->first); });
}

/// Calls visit(polygons, t_exit, leaf) for each leaf the ray passes within the interval, nearest
/// first, until visit returns true or the ray leaves the world or the interval.
template <class Visit>
void walk_octree(const OctreeTree& tree, const Ray& ray, Interval t, Visit&& visit) {
    Interval inside;
    if (clip_to_box(ray, tree.world, t, inside)) {
        walk_octree_inside(tree, ray, inside, std::forward<Visit>(visit));
    }
}

}  // namespace rt
