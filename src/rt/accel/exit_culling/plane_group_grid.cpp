#include "rt/accel/exit_culling/plane_group_grid.h"

#include <algorithm>
#include <cmath>

#include "rt/geometry/ray_polygon.h"

namespace rt {

namespace {

// Relative headroom on a bound, for the rounding of computing it.
constexpr double kSlack = 1.0 + 1e-9;
// Cells a side, at most: a group of n polygons gets about sqrt(n) a side.
constexpr int kMostCellsPerSide = 32;
// The reach boxes are listed grown by this share of the group's extent (and at least its
// rounding): a query whose tolerance is larger says it is unsure. Away from edge-on the
// tolerance is about 2^-40 / 1e-6 of the scale at most, far below.
constexpr double kMarginShare = 1e-5;

double largest_coordinate(const Vec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// The cell along one axis, clamped to the grid. NaN only for an axis of one cell (0 times an
// infinite difference), whose cell is 0.
int cell_along(double coordinate, double lo, double per_length, int cells) {
    const double at = std::floor((coordinate - lo) * per_length);
    if (!(at > 0.0)) {
        return 0;
    }
    return at < cells - 1 ? static_cast<int>(at) : cells - 1;
}

}  // namespace

std::uint32_t PlaneGroupGrids::add(const Vec3& normal, std::span<const std::uint32_t> members,
                                   std::span<const Box3> reach_boxes) {
    Grid grid;
    grid.normal = normal;
    const Vec3 a{std::fabs(normal.x), std::fabs(normal.y), std::fabs(normal.z)};
    const int drop = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    grid.axis = {drop == 0 ? 1 : 0, drop == 2 ? 1 : 2};
    Box3 all;
    for (const std::uint32_t id : members) {
        all.add(reach_boxes[id]);
        if (boxes_.size() <= id) {
            boxes_.resize(id + 1);
        }
        boxes_[id] = reach_boxes[id];
    }
    grid.margin = std::max(kMarginShare * all.largest_extent(), 1e-12 * all.magnitude());
    const Box3 grown = all.grown(grid.margin);
    const int side =
        std::clamp(2 * static_cast<int>(std::ceil(std::sqrt(static_cast<double>(members.size())))),
                   1, kMostCellsPerSide);
    for (std::size_t k = 0; k < 2; ++k) {
        const int axis = grid.axis[k];
        const double length = grown.hi[axis] - grown.lo[axis];
        grid.lo[k] = grown.lo[axis];
        // One cell along an axis of no length, or of so little that its cells would be
        // infinitely many a unit.
        const bool cut = length > 0.0 && std::isfinite(side / length);
        grid.cells[k] = cut ? side : 1;
        grid.per_length[k] = cut ? side / length : 0.0;
    }
    grid.first_cell = static_cast<std::uint32_t>(cell_starts_.size() - 1);
    for (int i = 0; i < grid.cells[0]; ++i) {
        for (int j = 0; j < grid.cells[1]; ++j) {
            const std::array<int, 2> at{i, j};
            // The cell, grown by a millionth of its size for the rounding of cell_along.
            std::array<double, 2> cell_lo{};
            std::array<double, 2> cell_hi{};
            for (std::size_t k = 0; k < 2; ++k) {
                const double size =
                    grid.per_length[k] > 0.0 ? 1.0 / grid.per_length[k] : Box3::kInfinity;
                const double room = 1e-6 * size;
                cell_lo[k] = at[k] == 0 ? -Box3::kInfinity : grid.lo[k] + at[k] * size - room;
                cell_hi[k] = at[k] == grid.cells[k] - 1 ? Box3::kInfinity
                                                        : grid.lo[k] + (at[k] + 1) * size + room;
            }
            for (const std::uint32_t id : members) {
                const Box3 box = reach_boxes[id].grown(grid.margin);
                bool meets = true;
                for (std::size_t k = 0; k < 2; ++k) {
                    const int axis = grid.axis[k];
                    meets = meets && box.lo[axis] <= cell_hi[k] && box.hi[axis] >= cell_lo[k];
                }
                if (meets) {
                    cell_members_.push_back(id);
                }
            }
            cell_starts_.push_back(static_cast<std::uint32_t>(cell_members_.size()));
        }
    }
    grids_.push_back(grid);
    return static_cast<std::uint32_t>(grids_.size() - 1);
}

bool PlaneGroupGrids::add_candidates(std::uint32_t grid_index, const Ray& ray, const Vec3& leader,
                                     double scale, std::span<std::uint32_t> out,
                                     std::uint32_t& count) const {
    const Grid& grid = grids_[grid_index];
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    const double denominator = dot(grid.normal, d);
    if (!certainly_not_edge_on(denominator, d)) {
        return false;  // near edge-on the exact test takes corner depths
    }
    const double along = plane_depth(ray, grid.normal, leader, denominator);
    const Vec3 x = o + d * along;
    const Vec3& n = grid.normal;
    const double n1 = std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z);
    const double size = scale * (1.0 + 0x1p-20);
    const double o_size = largest_coordinate(o);
    const double d_size = largest_coordinate(d);
    const double spread = (0x1p-40 * n1 * size + 0x1p-48 * n1 * (size + o_size)) * (1.0 + 0x1p-46);
    const double tolerance = (spread / std::fabs(denominator) * d_size +
                              0x1p-50 * (o_size + std::fabs(along) * d_size)) *
                             kSlack;
    // Half the margin: the other half covers the rounding of x's cell (see the header).
    if (!is_finite(x) || !(tolerance <= 0.5 * grid.margin)) {
        return false;
    }
    const int i = cell_along(x[grid.axis[0]], grid.lo[0], grid.per_length[0], grid.cells[0]);
    const int j = cell_along(x[grid.axis[1]], grid.lo[1], grid.per_length[1], grid.cells[1]);
    const std::size_t cell = grid.first_cell + static_cast<std::size_t>(i * grid.cells[1] + j);
    for (std::uint32_t k = cell_starts_[cell]; k < cell_starts_[cell + 1]; ++k) {
        const std::uint32_t id = cell_members_[k];
        const Box3& box = boxes_[id];
        const bool holds = x.x >= box.lo.x - tolerance && x.x <= box.hi.x + tolerance &&
                           x.y >= box.lo.y - tolerance && x.y <= box.hi.y + tolerance &&
                           x.z >= box.lo.z - tolerance && x.z <= box.hi.z + tolerance;
        if (!holds) {
            continue;
        }
        if (count == out.size()) {
            return false;
        }
        out[count++] = id;
    }
    return true;
}

std::size_t PlaneGroupGrids::memory_bytes() const {
    return grids_.capacity() * sizeof(Grid) + cell_starts_.capacity() * sizeof(std::uint32_t) +
           cell_members_.capacity() * sizeof(std::uint32_t) + boxes_.capacity() * sizeof(Box3);
}

}  // namespace rt
