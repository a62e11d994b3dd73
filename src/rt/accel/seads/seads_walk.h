// The 3D-DDA through a SEADS grid: every voxel the ray passes, in order along the ray, each with
// the t at which the ray leaves it; runs of empty voxels may be leapt over at once.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "rt/accel/seads/seads_grid.h"
#include "rt/core/prefetch.h"

namespace rt {

/// Whether the walk may leap over empty space (the grid's clearance) or must call visit for
/// every voxel (-tv counts them, and describe_walk lists them).
enum class EmptySpace { Leap, VisitEach };

/// The walk's position: the voxel, and where the ray crosses the next voxel plane on each axis.
/// Each plane's t comes from the plane's number (so leaps and steps agree), then one voxel's width
/// in t per step (Amanatides and Woo). The sum's rounding after even 3 x 1024 steps is some 1e-13
/// of t, far below the fudge; the voxel number itself is kept in integers.
class SeadsCursor {
public:
    /// `inverse[a]`: 1 / ray.direction[a] on each axis the ray moves along.
    SeadsCursor(const SeadsGrid& grid, const Ray& ray, const Vec3& inverse, double t_start)
        : grid_(grid),
          ray_(ray),
          side_(grid.side),
          voxels_(grid.offsets.size() - 1),
          inverse_(inverse),
          per_voxel_(grid.per_voxel) {
        const std::ptrdiff_t side = grid.side;
        for (int a = 0; a < 3; ++a) {
            const double d = ray.direction[a];
            cell_[a] = cell_at(a, t_start, 0, grid.side - 1);
            step_[a] = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
            t_delta_[a] = step_[a] == 0 ? 0.0 : grid.voxel_size[a] * std::fabs(inverse_[a]);
        }
        stride_[0] = step_[0];
        stride_[1] = step_[1] * side;
        stride_[2] = step_[2] * side * side;
        aim();
        voxel_ = grid.index(cell_[0], cell_[1], cell_[2]);
    }

    std::size_t voxel() const { return voxel_; }
    const int* cell() const { return cell_; }

    /// The axis of the nearest voxel plane ahead, and its t: where the ray leaves the voxel.
    int exit_axis() const {
        return t_next_[0] < t_next_[1] ? (t_next_[0] < t_next_[2] ? 0 : 2)
                                       : (t_next_[1] < t_next_[2] ? 1 : 2);
    }
    double exit_t(int axis) const { return t_next_[axis]; }

    /// The numbers of the voxel across `axis` and of the one after it on the same axis, for
    /// prefetching what their visits will read; kNoVoxelAhead where a number falls outside the
    /// grid's table. The second is a guess: the walk may step on another axis first. The true
    /// voxel after (the least of the three plane crossings) measured 5-8 % slower on meshes that
    /// fit in the cache, and no faster on the large ones. Across a face of the grid a number
    /// names some other voxel, which is harmless.
    static constexpr std::size_t kNoVoxelAhead = std::numeric_limits<std::size_t>::max();
    struct Ahead {
        std::size_t next;
        std::size_t after;
    };
    Ahead voxels_ahead(int axis) const {
        const std::size_t next = voxel_ + static_cast<std::size_t>(stride_[axis]);
        if (next >= voxels_) {
            return {kNoVoxelAhead, kNoVoxelAhead};
        }
        const std::size_t after = next + static_cast<std::size_t>(stride_[axis]);
        return {next, after < voxels_ ? after : kNoVoxelAhead};
    }

    /// Into the next voxel across `axis`; false if that leaves the grid.
    bool step(int axis) {
        cell_[axis] += step_[axis];
        if (cell_[axis] < 0 || cell_[axis] >= side_) {
            return false;
        }
        voxel_ += static_cast<std::size_t>(stride_[axis]);
        t_next_[axis] += t_delta_[axis];
        return true;
    }

    /// Where the ray leaves the cube of voxels within `reach` of this one, and through which axis.
    double cube_exit(int reach, int& axis) const {
        constexpr double kNever = std::numeric_limits<double>::infinity();
        double t_leave = kNever;
        axis = 0;
        for (int a = 0; a < 3; ++a) {
            if (step_[a] != 0) {
                const double ta = plane_t(a, cell_[a] + (step_[a] > 0 ? reach + 1 : -reach));
                if (ta < t_leave) {
                    t_leave = ta;
                    axis = a;
                }
            }
        }
        return t_leave;
    }

    /// Out of that cube at t_leave through `axis`, as the octree walk finds its next leaf: across
    /// the face by an integer step, within it from where the ray crosses, never back against the
    /// ray's direction. False if that leaves the grid.
    bool leap(int reach, int axis, double t_leave) {
        for (int a = 0; a < 3; ++a) {
            if (a == axis || step_[a] == 0) {
                continue;
            }
            const int low = step_[a] > 0 ? cell_[a] : std::max(cell_[a] - reach, 0);
            const int high = step_[a] > 0 ? std::min(cell_[a] + reach, side_ - 1) : cell_[a];
            cell_[a] = cell_at(a, t_leave, low, high);
        }
        cell_[axis] += step_[axis] * (reach + 1);
        if (cell_[axis] < 0 || cell_[axis] >= side_) {
            return false;
        }
        aim();
        voxel_ = grid_.index(cell_[0], cell_[1], cell_[2]);
        return true;
    }

private:
    // The voxel along `a` holding the ray's point at `at_t`, clamped to [low, high].
    int cell_at(int a, double at_t, int low, int high) const {
        const double x = ray_.origin[a] + at_t * ray_.direction[a];
        // A product with the reciprocal rather than a division: the rounding differs by an ulp
        // or so, far below the fudge, and a leap costs less.
        const double c = std::floor((x - grid_.world.lo[a]) * per_voxel_[a]);
        return static_cast<int>(std::clamp(c, static_cast<double>(low), static_cast<double>(high)));
    }
    double plane_t(int a, int k) const {
        return (grid_.world.lo[a] + k * grid_.voxel_size[a] - ray_.origin[a]) * inverse_[a];
    }
    void aim() {
        constexpr double kNever = std::numeric_limits<double>::infinity();
        for (int a = 0; a < 3; ++a) {
            t_next_[a] = step_[a] == 0 ? kNever : plane_t(a, cell_[a] + (step_[a] > 0 ? 1 : 0));
        }
    }

    const SeadsGrid& grid_;
    const Ray& ray_;
    // Copies, not reads through grid_: the compiler cannot tell stores to cell_ from them.
    int side_;
    std::size_t voxels_;
    Vec3 inverse_;
    Vec3 per_voxel_;
    int cell_[3] = {0, 0, 0};
    int step_[3] = {0, 0, 0};
    double t_next_[3] = {0.0, 0.0, 0.0};
    double t_delta_[3] = {0.0, 0.0, 0.0};
    std::ptrdiff_t stride_[3] = {0, 0, 0};
    std::size_t voxel_ = 0;
};

/// A voxel number that stands for no voxel with polygons (an empty one, or a leap).
inline constexpr std::size_t kNoSeadsVoxel = std::numeric_limits<std::size_t>::max();

/// The walk for a ray already clipped to the world (`inside` is what clip_to_box gave for the
/// interval), calling visit(voxel, t_exit, cell): `voxel` the number of a voxel with polygons,
/// kNoSeadsVoxel for an empty one or a leap. `inverse[a]` is 1 / ray.direction[a] on each axis
/// the ray moves along. The walk itself reads only the clearance table. Before each visit it
/// calls ahead(next, after) with SeadsCursor::voxels_ahead's numbers, for the caller to ask the
/// cache for what the next visits will read.
template <class Visit, class Ahead>
void walk_seads_voxels(const SeadsGrid& grid, const Ray& ray, const Vec3& inverse, Interval inside,
                       Visit&& visit, EmptySpace empty, Ahead&& ahead) {
    SeadsCursor at(grid, ray, inverse, inside.min);
    while (true) {
        const int clearance = grid.clearance[at.voxel()];
        if (clearance >= 2 && empty == EmptySpace::Leap) {
            // Every voxel within `reach` of this one on every axis is empty: leave that cube.
            const int reach = clearance - 1;
            int axis = 0;
            const double t_leave = at.cube_exit(reach, axis);
            if (visit(kNoSeadsVoxel, t_leave, at.cell()) || !(t_leave < inside.max) ||
                !at.leap(reach, axis, t_leave)) {
                return;
            }
            continue;
        }
        const int axis = at.exit_axis();
        const double t_exit = at.exit_t(axis);
        const SeadsCursor::Ahead voxels = at.voxels_ahead(axis);
        ahead(voxels.next, voxels.after);
        const std::size_t voxel = clearance == 0 ? at.voxel() : kNoSeadsVoxel;
        if (visit(voxel, t_exit, at.cell()) || !(t_exit < inside.max) || !at.step(axis)) {
            return;
        }
    }
}

/// The same, calling visit(polygons, t_exit, cell) with the voxel's polygon ids.
template <class Visit>
void walk_seads_inside(const SeadsGrid& grid, const Ray& ray, Interval inside, Visit&& visit,
                       EmptySpace empty = EmptySpace::Leap) {
    const Vec3 inverse{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    walk_seads_voxels(
        grid, ray, inverse, inside,
        [&](std::size_t voxel, double t_exit, const int* cell) {
            return visit(
                voxel == kNoSeadsVoxel ? std::span<const std::uint32_t>{} : grid.voxel(voxel),
                t_exit, cell);
        },
        empty,
        [&](std::size_t next, std::size_t) {
            if (next != SeadsCursor::kNoVoxelAhead) {
                prefetch(grid.offsets.data() + next);
            }
        });
}

/// Calls visit(polygons, t_exit, voxel) for each voxel (voxel: its x, y, z) the ray passes within
/// the interval, nearest first, until visit returns true or the ray leaves the grid or the
/// interval. With EmptySpace::Leap, a cube of empty voxels around the ray is one visit with no
/// polygons, whose t_exit is where the ray leaves the cube: to a near-hit rule that is the same
/// as visiting each of them, since none has a polygon.
template <class Visit>
void walk_seads(const SeadsGrid& grid, const Ray& ray, Interval t, Visit&& visit,
                EmptySpace empty = EmptySpace::Leap) {
    Interval inside;
    if (clip_to_box(ray, grid.world, t, inside)) {
        walk_seads_inside(grid, ray, inside, std::forward<Visit>(visit), empty);
    }
}

}  // namespace rt
