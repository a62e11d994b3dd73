// The inclusion-cone table of exit-ray culling (manual part three and the -De switch): for each
// cell of a coarse grid over the world and each bin of directions, whether a ray starting in the
// cell with a direction in the bin can hit anything at all. Conservative: "nothing ahead" is
// only ever said when no polygon can be hit (exit_culling_table.cpp argues why).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rt/accel/exit_culling/direction_bins.h"
#include "rt/accel/exit_culling/occupied_cells.h"
#include "rt/core/ray.h"

namespace rt {

class ExitCullingTable {
public:
    /// `resolution` grid cells along each axis (1..64), `bins_per_side` bins along each edge of
    /// each of the 6 faces of the direction cube (1..16).
    /// `threads` build it (0: one a core for a large scene, see parallel_parts.h); the table is
    /// the same for any number.
    ExitCullingTable(const Scene& scene, int resolution, int bins_per_side, int threads = 0);
    /// The same with the rounding allowances given (tests widen them).
    ExitCullingTable(const CullingFrame& frame, const Scene& scene, int resolution,
                     int bins_per_side, int threads = 0);

    /// True only if no polygon can be hit by the ray at any t > t.min. Never true for t.min < 0,
    /// for a zero or non-finite ray, or for an origin more than 100 scene diagonals away.
    bool nothing_ahead(const Ray& ray, Interval t) const;

    /// Whether a ray starting at `origin` is surely not culled: the origin lies in the world, in
    /// a cell whose every bin is set (every cell a polygon crosses). No division, no clipping:
    /// rays leaving a surface, most of all rays, end here (nothing_ahead() asks it first).
    bool starts_in_full_cell(const Vec3& origin) const {
        const Box3& world = cells_.world();
        const bool inside = origin.x >= world.lo.x && origin.x <= world.hi.x &&
                            origin.y >= world.lo.y && origin.y <= world.hi.y &&
                            origin.z >= world.lo.z && origin.z <= world.hi.z;
        return inside && full_[static_cast<std::size_t>(cells_.cell_of(origin))] != 0;
    }

    /// Where hit points can be: the cells, and in each the box of every reach meeting it.
    const OccupiedCells& cells() const { return cells_; }
    int resolution() const { return cells_.resolution(); }
    int bins_per_side() const { return bins_.side(); }
    std::size_t occupied_cells() const { return cells_.occupied_count(); }
    /// The share of (cell, bin) entries that say "nothing ahead".
    double empty_fraction() const;
    std::size_t memory_bytes() const;
    /// Per cell (x + R (y + R z)), one 16-bit mask per row of direction bins (DirectionBins).
    std::span<const std::uint16_t> bin_rows() const { return rows_; }

private:
    std::span<const std::uint16_t> region(int cell) const {
        return {rows_.data() + static_cast<std::size_t>(cell) * bins_.rows(),
                static_cast<std::size_t>(bins_.rows())};
    }
    /// The grazing pass over every reach, each thread or-ing into its own copy of the rows.
    void add_all_grazing(const ReachSource& reaches, int threads);
    /// The directions towards the reaches' occupied cells, from one cell.
    void fill_region(int cell);
    /// The directions of grazing hits on one polygon, from every cell they may start in.
    void add_grazing(const PolygonReach& reach, std::vector<std::uint16_t>& band,
                     std::span<std::uint16_t> rows) const;
    /// Sets full_ from rows_.
    void find_full_cells();
    /// The cell a ray enters the world in (its own cell if it starts inside); -1 if it never
    /// does. `inverse` holds 1 / direction per axis.
    int entry_cell(const Ray& ray, const Vec3& inverse) const;

    OccupiedCells cells_;
    DirectionBins bins_;
    std::vector<std::uint16_t> rows_;  ///< per cell, bins_.rows() row masks
    std::vector<std::uint8_t> full_;   ///< per cell: 1 when every bin of its region is set
};

}  // namespace rt
