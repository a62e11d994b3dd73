// What both octree fills share: the checks on the settings, the node pool with its -ol limit, and
// the step that hands a node's polygons to the children they touch.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rt/accel/octree/octree_tree.h"

namespace rt {

/// A node on the lattice: its lowest corner and side in finest steps, and its level.
struct OctreeCell {
    std::array<std::int64_t, 3> origin{};
    std::int64_t size = 1;
    int level = 0;

    OctreeCell child(int c) const;
};

/// Everything a fill needs besides the recursion itself.
class OctreeFill {
public:
    /// Checks the depth and -ol, sets up the world box; throws SettingError for bad settings.
    OctreeFill(const Scene& scene, const OctreeBuildSettings& settings, bool no_fudge);

    OctreeTree& tree() { return tree_; }
    /// Every polygon's id (the root's contents).
    std::vector<std::uint32_t> all_polygons() const;
    /// Whether a node of this level holding `count` polygons is split.
    bool splits(int level, std::size_t count) const {
        return count > kMaxLeafPolygons && level < tree_.depth;
    }
    /// Appends 8 children, each a leaf for now; returns the first's index. Throws SettingError
    /// naming -ol when the pool is full.
    std::uint32_t allocate_children() { return allocate_children(tree_); }
    /// The same on another tree (a subtree built apart, to be spliced into tree()).
    std::uint32_t allocate_children(OctreeTree& tree) const;
    /// Turns node `index` into a leaf holding these polygons.
    void make_leaf(std::uint32_t index, const std::vector<std::uint32_t>& polygons) {
        make_leaf(tree_, index, polygons);
    }
    void make_leaf(OctreeTree& tree, std::uint32_t index,
                   const std::vector<std::uint32_t>& polygons) const;
    /// Throws the SettingError allocate_children() gives when the pool holds `nodes` > -ol nodes.
    void check_node_count(std::size_t nodes) const;
    /// Sends each of the node's polygons to every child it touches (each grown by the fudge).
    void split(const OctreeCell& cell, const std::vector<std::uint32_t>& polygons,
               std::array<std::vector<std::uint32_t>, 8>& children) const;

private:
    Box3 cell_box(const OctreeCell& cell) const;
    /// Bit c set: the polygon's box reaches child c (each grown by the fudge).
    int children_reached(std::uint32_t polygon, const double middle[3]) const;
    /// Whether the polygon touches the child grown by the fudge.
    bool touches(std::uint32_t polygon, const OctreeCell& child) const;

    const Scene& scene_;
    OctreeTree tree_;
    std::vector<Box3> bounds_;  ///< each polygon's box, grown by the fudge
    double fudge_ = 0.0;
    std::uint64_t max_nodes_ = 0;
    int octlist_power_ = kDefaultOctlistPower;
};

}  // namespace rt
