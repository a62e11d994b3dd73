// Where hit points can be: a coarse grid over the world, and in each cell the box of every
// polygon reach (hit_regions/polygon_reach.h) that meets it, cut to the cell. Exit culling asks,
// from each cell, which directions lead to one of these boxes; a tree over them lets it skip groups
// of boxes whose directions it already has.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "rt/accel/hit_regions/polygon_reach.h"
#include "rt/core/bounds.h"
#include "rt/scene/scene.h"

namespace rt {

/// The rounding allowances for a scene: see occupied_cells.cpp.
struct CullingFrame {
    Box3 positions;          ///< the box of the scene's corners
    double far_limit = 0.0;  ///< farthest ray origin from `positions` that may be culled
    double rounding = 0.0;   ///< for polygon_reach()
    double margin = 0.0;     ///< for cells and entry points
};
CullingFrame culling_frame(const Scene& scene);

/// The reach of each polygon of a scene, computed when asked: the build asks for each one up to
/// three times rather than keep them all (168 bytes a polygon, 1.7 GB for 10M triangles).
struct ReachSource {
    const Scene* scene = nullptr;
    double rounding = 0.0;  ///< CullingFrame::rounding
    std::size_t count() const { return scene->polygons.size(); }
    PolygonReach operator()(std::size_t id) const {
        return polygon_reach(*scene, static_cast<std::uint32_t>(id), 0.0, rounding);
    }
};

class OccupiedCells {
public:
    /// `resolution` cells along each axis (1..64) of the box of every reach (both kinds), filled
    /// by `threads` threads (the same cells for any number).
    OccupiedCells(const CullingFrame& frame, const ReachSource& reaches, int resolution,
                  int threads = 1);

    /// Every reach box, grown by margin(): no hit point lies outside it, or within margin() of
    /// its boundary.
    const Box3& world() const { return world_; }
    const CullingFrame& frame() const { return frame_; }
    double margin() const { return frame_.margin; }
    int resolution() const { return resolution_; }

    /// The cell holding a point of the world (clamped at the boundary), as x + R (y + R z).
    int cell_of(const Vec3& p) const {
        return axis_cell(0, p.x) +
               resolution_ * (axis_cell(1, p.y) + resolution_ * axis_cell(2, p.z));
    }
    /// The cells along each axis whose boxes, grown by `grow` (as Box3::grown grows them), may meet
    /// the box: every cell whose intersection with it is not empty, found from its corners' own
    /// cells (one more each way, as cells and boundaries are rounded separately) and the exact
    /// boundaries.
    void cell_range(const Box3& box, double grow, int first[3], int last[3]) const;
    Box3 cell_box(int cell) const;
    Box3 cell_box(int x, int y, int z) const {
        return {{boundaries_[0][x], boundaries_[1][y], boundaries_[2][z]},
                {boundaries_[0][x + 1], boundaries_[1][y + 1], boundaries_[2][z + 1]}};
    }

    /// A binary tree over the occupied cells' boxes, root first; leaves have no children.
    struct Node {
        Box3 box;
        std::int32_t first_child = -1;  ///< the second child follows it
    };
    const std::vector<Node>& tree() const { return tree_; }
    std::size_t occupied_count() const { return occupied_; }
    std::size_t memory_bytes() const { return tree_.capacity() * sizeof(Node); }

private:
    // A product with the reciprocal, not a division, and truncation after the clamp (which makes
    // the value non-negative) rather than floor(): a few ulps of the world's size apart at most,
    // far below margin(), and without the division and the libm call that made this the
    // costliest step of a culling test. Inline: every ray the culling layer sees comes here.
    int axis_cell(int axis, double coordinate) const {
        const double scaled = (coordinate - world_.lo[axis]) * inverse_cell_size_[axis];
        return static_cast<int>(std::clamp(scaled, 0.0, top_cell_));
    }
    double boundary(int axis, int index) const;
    void fill(const ReachSource& reaches, std::vector<Box3>& cells, int threads) const;
    void add_reach(const PolygonReach& reach, std::vector<Box3>& cells) const;
    void build_node(const std::vector<Box3>& leaves, std::size_t begin, std::size_t end,
                    std::size_t slot);

    CullingFrame frame_;
    Box3 world_;
    int resolution_ = 1;
    Vec3 cell_size_;
    Vec3 inverse_cell_size_;                         ///< 0 along an axis of no extent (one cell)
    double top_cell_ = 0.0;                          ///< resolution - 1
    std::array<std::vector<double>, 3> boundaries_;  ///< boundary(axis, 0..resolution), looked up
    std::vector<Node> tree_;
    std::size_t occupied_ = 0;
};

}  // namespace rt
