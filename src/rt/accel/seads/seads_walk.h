// The 3D-DDA through a SEADS grid: every voxel the ray passes, in order along the ray, each with
// the t at which the ray leaves it; runs of empty voxels may be leapt over at once.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "rt/accel/seads/seads_grid.h"

namespace rt {

/// Whether the walk may leap over empty space (the grid's clearance) or must call visit for
/// every voxel (-tv counts them, and describe_walk lists them).
enum class EmptySpace { Leap, VisitEach };

/// Calls visit(polygons, t_exit, voxel) for each voxel (voxel: its x, y, z) the ray passes within
/// the interval, nearest first, until visit returns true or the ray leaves the grid or the
/// interval. With EmptySpace::Leap, a cube of empty voxels around the ray is one visit with no
/// polygons, whose t_exit is where the ray leaves the cube: to a near-hit rule that is the same
/// as visiting each of them, since none has a polygon.
/// walk_seads for a ray already clipped to the world: `inside` is what clip_to_box gave for the
/// interval (callers that clip first skip the rest of their setup for rays that miss).
template <class Visit>
void walk_seads_inside(const SeadsGrid& grid, const Ray& ray, Interval inside, Visit&& visit,
                       EmptySpace empty = EmptySpace::Leap) {
    constexpr double kNever = std::numeric_limits<double>::infinity();
    const Vec3 per_voxel{1.0 / grid.voxel_size.x, 1.0 / grid.voxel_size.y, 1.0 / grid.voxel_size.z};
    // The voxel along `a` holding the ray's point at `at_t`, clamped to [low, high].
    auto cell_at = [&](int a, double at_t, int low, int high) {
        const double x = ray.origin[a] + at_t * ray.direction[a];
        const double c = std::floor((x - grid.world.lo[a]) * per_voxel[a]);
        return static_cast<int>(std::clamp(c, static_cast<double>(low), static_cast<double>(high)));
    };
    int cell[3];
    int step[3];
    for (int a = 0; a < 3; ++a) {
        const double d = ray.direction[a];
        cell[a] = cell_at(a, inside.min, 0, grid.side - 1);
        step[a] = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
    }
    // Where the ray crosses voxel plane k along `a`: from the plane's number each time (so
    // leaps and steps agree), then one voxel's width in t per step (Amanatides and Woo). The
    // sum's rounding after even 3 x 1024 steps is some 1e-13 of t, far below the fudge; the
    // voxel number itself is kept in integers.
    const Vec3 inverse{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    auto plane_t = [&](int a, int k) {
        return (grid.world.lo[a] + k * grid.voxel_size[a] - ray.origin[a]) * inverse[a];
    };
    double t_next[3];
    double t_delta[3];
    auto aim = [&] {
        for (int a = 0; a < 3; ++a) {
            t_next[a] = step[a] == 0 ? kNever : plane_t(a, cell[a] + (step[a] > 0 ? 1 : 0));
        }
    };
    for (int a = 0; a < 3; ++a) {
        t_delta[a] = step[a] == 0 ? 0.0 : grid.voxel_size[a] * std::fabs(inverse[a]);
    }
    aim();
    const std::ptrdiff_t side = grid.side;
    const std::ptrdiff_t stride[3] = {step[0], step[1] * side, step[2] * side * side};
    std::size_t voxel = grid.index(cell[0], cell[1], cell[2]);
    while (true) {
        const int clearance = grid.clearance[voxel];
        if (clearance >= 2 && empty == EmptySpace::Leap) {
            // Every voxel within `reach` of this one on every axis is empty: leave that cube
            // through its nearest far face. The cell beyond is found as the octree walk finds its
            // next leaf: across the face by an integer step, within it from where the ray
            // crosses, never back against the ray's direction.
            const int reach = clearance - 1;
            double t_leave = kNever;
            int axis = 0;
            for (int a = 0; a < 3; ++a) {
                if (step[a] != 0) {
                    const double ta = plane_t(a, cell[a] + (step[a] > 0 ? reach + 1 : -reach));
                    if (ta < t_leave) {
                        t_leave = ta;
                        axis = a;
                    }
                }
            }
            if (visit(std::span<const std::uint32_t>{}, t_leave, static_cast<const int*>(cell)) ||
                !(t_leave < inside.max)) {
                return;
            }
            for (int a = 0; a < 3; ++a) {
                if (a == axis || step[a] == 0) {
                    continue;
                }
                const int low = step[a] > 0 ? cell[a] : std::max(cell[a] - reach, 0);
                const int high = step[a] > 0 ? std::min(cell[a] + reach, grid.side - 1) : cell[a];
                cell[a] = cell_at(a, t_leave, low, high);
            }
            cell[axis] += step[axis] * (reach + 1);
            if (cell[axis] < 0 || cell[axis] >= grid.side) {
                return;
            }
            aim();
            voxel = grid.index(cell[0], cell[1], cell[2]);
            continue;
        }
        const int axis = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2)
                                               : (t_next[1] < t_next[2] ? 1 : 2);
        const double t_exit = t_next[axis];
        // The next voxel's offsets asked for now, to arrive while this one is tested.
        if (const std::size_t next = voxel + static_cast<std::size_t>(stride[axis]);
            next < grid.offsets.size()) {
            __builtin_prefetch(grid.offsets.data() + next);
        }
        const std::span<const std::uint32_t> polygons =
            clearance == 0 ? grid.voxel(voxel) : std::span<const std::uint32_t>{};
        if (visit(polygons, t_exit, static_cast<const int*>(cell))) {
            return;
        }
        if (!(t_exit < inside.max)) {
            return;
        }
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= grid.side) {
            return;
        }
        voxel += static_cast<std::size_t>(stride[axis]);
        t_next[axis] += t_delta[axis];
    }
}

template <class Visit>
void walk_seads(const SeadsGrid& grid, const Ray& ray, Interval t, Visit&& visit,
                EmptySpace empty = EmptySpace::Leap) {
    Interval inside;
    if (clip_to_box(ray, grid.world, t, inside)) {
        walk_seads_inside(grid, ray, inside, std::forward<Visit>(visit), empty);
    }
}

}  // namespace rt
