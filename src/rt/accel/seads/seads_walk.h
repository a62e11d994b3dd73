// The 3D-DDA through a SEADS grid: every voxel the ray passes, in order along the ray, each with
// the t at which the ray leaves it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "rt/accel/seads/seads_grid.h"

namespace rt {

/// Calls visit(polygons, t_exit, voxel) for each voxel (voxel: its x, y, z) the ray passes within
/// the interval, nearest first, until visit returns true or the ray leaves the grid or the
/// interval.
template <class Visit>
void walk_seads(const SeadsGrid& grid, const Ray& ray, Interval t, Visit&& visit) {
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
