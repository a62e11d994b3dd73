// Which polygons of a plane group (in_plane_group, geometry/ray_polygon.h) a ray may hit, found
// from where its line crosses their common plane: a checkerboard floor seen from a box standing
// on it. The leaving table (leaving_table.h) then names those few squares as the ray's only
// candidates instead of sending the ray through the whole structure.
//
// Why the squares it names hold every square the exact test can report hit. The group's polygons
// share their normal n bit for bit, so the exact test divides each one's numerator dot(n, q0 - o)
// by the same denominator D = dot(n, d), and, away from edge-on (certainly_not_edge_on), reports
// t_Q = dot(n, q0 - o) / D, whose point o + t_Q d lies in Q's reach box (polygon_reach, the
// non-grazing box). The query computes the leader's t_L and the point x = o + t_L d. The
// numerators of two polygons of the group differ by at most S = (2^-40 |n|_1 s + 2^-48 |n|_1
// (s + |o|)) (1 + 2^-46), with s the group's largest |coordinate| of a corner 0: the group's own
// spread, and each dot product's rounding (plane_group_certainly_missed argues the same terms).
// So |t_Q - t_L| <= S / |D| + 2^-52 |t_L| (the two divisions' rounding, with room), and each
// coordinate of x is within 2^-52 (|o| + |t_L| |d|) of o + t_L d. Each coordinate of o + t_Q d
// is then within tol = (S / |D| |d|_max + 2^-50 (|o|_max + |t_L| |d|_max)) (1 + 1e-9) of x's:
// Q's reach box grown by tol holds x. The grid lists, in each cell, every polygon whose reach box
// grown by the grid's margin G meets the cell grown by a millionth of its size, and the query
// answers only when tol <= G / 2. x's computed cell index (one subtraction and one product,
// clamped to the grid) puts x at most 2^-52 (2 |x| + the grid's length) from the cell it names,
// where |x| is at most the group's magnitude plus G inside the grid (the edge cells reach to
// infinity). That is under G / 2, which is at least 1e-12 times the magnitude; so Q's box grown
// by G meets the named cell, which lists Q, and the query keeps Q as its box grown by tol holds x.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rt/core/bounds.h"
#include "rt/core/ray.h"

namespace rt {

class PlaneGroupGrids {
public:
    static constexpr std::uint32_t kNoGrid = 0xffffffffu;

    /// Adds the grid of a group of polygons sharing the unit normal `normal` bit for bit:
    /// `members` are their ids and `reach_boxes` (indexed by id) their reach boxes for any ray.
    /// Returns the grid's index.
    std::uint32_t add(const Vec3& normal, std::span<const std::uint32_t> members,
                      std::span<const Box3> reach_boxes);

    /// Appends to out[count...] the group's polygons the ray may hit (see above): the group of
    /// grid `grid`, whose leader has corner 0 `leader` and whose corners 0 have no |coordinate|
    /// above `scale`. False when unsure (a ray near edge-on, a non-finite crossing) or when `out`
    /// is full; `count` is then not to be used.
    bool add_candidates(std::uint32_t grid, const Ray& ray, const Vec3& leader, double scale,
                        std::span<std::uint32_t> out, std::uint32_t& count) const;

    std::size_t memory_bytes() const;

private:
    struct Grid {
        Vec3 normal;                         ///< unit, the group's bit for bit
        std::array<int, 2> axis{0, 1};       ///< the two axes in the plane's projection
        std::array<double, 2> lo{};          ///< the grid's corner
        std::array<double, 2> per_length{};  ///< cells per unit length (0 for one cell)
        std::array<int, 2> cells{1, 1};
        double margin = 0.0;           ///< how far the listed reach boxes were grown
        std::uint32_t first_cell = 0;  ///< into cell_starts_
    };

    std::vector<Grid> grids_;
    /// Per cell of every grid, where its list starts in cell_members_, and one past the end.
    std::vector<std::uint32_t> cell_starts_{0};
    std::vector<std::uint32_t> cell_members_;
    /// Per listed polygon id, its reach box (polygons in no group hold an empty box).
    std::vector<Box3> boxes_;
};

}  // namespace rt
