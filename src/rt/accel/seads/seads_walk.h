// The 3D-DDA through a SEADS grid: every voxel the ray passes, in order along the ray, each with
// the t at which the ray leaves it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "rt/accel/seads/seads_grid.h"

namespace rt {

/// The default skip policy: every voxel is visited, empty or not.
struct VisitEveryVoxel {
    bool may_skip() const { return false; }
    void skipped(std::uint64_t) const {}
};

/// What cross_empty_macro_cell did: how many voxels it passed (0: none, the walk should step
/// voxel by voxel) and whether it left the grid.
struct MacroMove {
    std::uint64_t voxels = 0;
    bool left_grid = false;
};

/// Moves the walk (cell, t_next) from a voxel of an empty macro cell to the first voxel past it,
/// with the walk's own arithmetic: each axis's boundary t is the same running sum of t_delta the
/// voxel-by-voxel walk forms, and ties go to the higher axis as there. Moves nothing when the
/// walk would end inside the macro cell (its exit at or beyond t_max), so the voxel count stays
/// exact.
inline MacroMove cross_empty_macro_cell(const SeadsGrid& grid, const int* step,
                                        const double* t_delta, double t_max, int* cell,
                                        double* t_next) {
    double t_out[3];
    int to_face[3];
    for (int a = 0; a < 3; ++a) {
        const int base = cell[a] / kSeadsMacro * kSeadsMacro;
        to_face[a] = step[a] > 0   ? std::min(grid.side - 1, base + kSeadsMacro - 1) - cell[a]
                     : step[a] < 0 ? cell[a] - base
                                   : 0;
        t_out[a] = t_next[a];
        for (int k = 0; k < to_face[a]; ++k) {
            t_out[a] += t_delta[a];
        }
    }
    const int out = t_out[0] < t_out[1] ? (t_out[0] < t_out[2] ? 0 : 2)
                                        : (t_out[1] < t_out[2] ? 1 : 2);
    const double t_leave = t_out[out];
    if (!(t_leave < t_max)) {
        return {};
    }
    MacroMove move;
    move.voxels = 1 + static_cast<std::uint64_t>(to_face[out]);
    for (int b = 0; b < 3; ++b) {
        if (b == out) {
            continue;
        }
        // The steps along b the walk takes before its step out of the macro cell.
        while (t_next[b] < t_leave || (t_next[b] == t_leave && b > out)) {
            t_next[b] += t_delta[b];
            cell[b] += step[b];
            ++move.voxels;
        }
    }
    cell[out] += step[out] * (to_face[out] + 1);
    t_next[out] = t_leave + t_delta[out];
    move.left_grid = cell[out] < 0 || cell[out] >= grid.side;
    return move;
}

/// Calls visit(polygons, t_exit, voxel) for each voxel (voxel: its x, y, z) the ray passes within
/// the interval, nearest first, until visit returns true or the ray leaves the grid or the
/// interval.
///
/// When skip.may_skip() says visiting empty voxels cannot end the walk, an empty voxel in an
/// empty macro cell is not visited: the walk crosses the macro cell in one move and reports the
/// voxels it passed by skip.skipped(count). The move repeats the walk's own arithmetic (each
/// axis's boundary t is the same running sum of t_delta the voxel-by-voxel walk forms, and ties
/// go to the same axis), so the voxels visited after it, their t_exit and the voxel count are
/// exactly the voxel-by-voxel walk's.
template <class Visit, class Skip = VisitEveryVoxel>
void walk_seads(const SeadsGrid& grid, const Ray& ray, Interval t, Visit&& visit,
                Skip&& skip = Skip{}) {
    Interval inside;
    if (!clip_to_box(ray, grid.world, t, inside)) {
        return;
    }
    constexpr double kNever = std::numeric_limits<double>::infinity();
    const Vec3 start = ray.at(inside.min);
    int cell[3];
    int step[3];
    double t_next[3];
    for (int a = 0; a < 3; ++a) {
        const double d = ray.direction[a];
        const double c = std::floor((start[a] - grid.world.lo[a]) / grid.voxel_size[a]);
        cell[a] = static_cast<int>(std::clamp(c, 0.0, static_cast<double>(grid.side - 1)));
        step[a] = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
    }
    // The first boundary's t from the voxel number, then one voxel's width in t per step
    // (Amanatides and Woo). The sum's rounding after even 3 x 1024 steps is some 1e-13 of t, far
    // below the fudge; the voxel number itself is kept in integers.
    const Vec3 inverse{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    double t_delta[3];
    for (int a = 0; a < 3; ++a) {
        if (step[a] == 0) {
            t_next[a] = kNever;
            t_delta[a] = 0.0;
            continue;
        }
        const int plane = cell[a] + (step[a] > 0 ? 1 : 0);
        const double x = grid.world.lo[a] + plane * grid.voxel_size[a];
        t_next[a] = (x - ray.origin[a]) * inverse[a];
        t_delta[a] = grid.voxel_size[a] * std::fabs(inverse[a]);
    }
    const std::ptrdiff_t side = grid.side;
    const std::ptrdiff_t stride[3] = {step[0], step[1] * side, step[2] * side * side};
    std::size_t voxel = grid.index(cell[0], cell[1], cell[2]);
    while (true) {
        if (!grid.is_occupied(voxel) && skip.may_skip() &&
            !grid.macro_occupied_at(cell[0], cell[1], cell[2])) {
            const MacroMove move =
                cross_empty_macro_cell(grid, step, t_delta, inside.max, cell, t_next);
            if (move.voxels != 0) {
                skip.skipped(move.voxels);
                if (move.left_grid) {
                    return;
                }
                voxel = grid.index(cell[0], cell[1], cell[2]);
                continue;
            }
        }
        const int axis = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2)
                                               : (t_next[1] < t_next[2] ? 1 : 2);
        const double t_exit = t_next[axis];
        if (visit(grid.voxel_if_occupied(voxel), t_exit, static_cast<const int*>(cell))) {
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

}  // namespace rt
