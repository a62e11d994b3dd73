// The 3D-DDA through a SEADS grid: every voxel the ray passes, in order along the ray, each with
// the t at which the ray leaves it.
#pragma once

#include <algorithm>
#include <cmath>
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
    // Each boundary's t is computed afresh from the integer voxel number (not by adding deltas),
    // so the error stays that of a few products however long the walk (far below the fudge).
    const Vec3 inverse{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    auto boundary_t = [&](int a) {
        if (step[a] == 0) {
            return kNever;
        }
        const int plane = cell[a] + (step[a] > 0 ? 1 : 0);
        const double x = grid.world.lo[a] + plane * grid.voxel_size[a];
        return (x - ray.origin[a]) * inverse[a];
    };
    for (int a = 0; a < 3; ++a) {
        t_next[a] = boundary_t(a);
    }
    while (true) {
        const int axis = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2)
                                               : (t_next[1] < t_next[2] ? 1 : 2);
        const double t_exit = t_next[axis];
        if (visit(grid.voxel_if_occupied(grid.index(cell[0], cell[1], cell[2])), t_exit,
                  static_cast<const int*>(cell))) {
            return;
        }
        if (!(t_exit < inside.max)) {
            return;
        }
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= grid.side) {
            return;
        }
        t_next[axis] = boundary_t(axis);
    }
}

}  // namespace rt
