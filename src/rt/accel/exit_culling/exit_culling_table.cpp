// Why "nothing ahead" is safe. Suppose the ray-polygon test reports a hit at t > t.min >= 0 on a
// ray starting at p with direction d. The hit point Y = p + t d lies in that polygon's reach, so
// in the box of some occupied cell (occupied_cells.h), at least margin() inside the world box.
// - If p is inside the world box, p lies in the box of its cell grown by margin() (the cell is
//   found by a rounded product with the reciprocal cell size, wrong only within a few ulps of a
//   cell boundary).
// - If p is outside, the ray must cross the world box to reach Y; q = p + t_entry d, where it
//   enters, is computed to within far below margin() (origins farther than 100 diagonals from
//   the corners are not culled), so q too lies in its cell's box grown by margin(), and Y = q + (t
//   - t_entry) d with t > t_entry. A ray that misses the world box hits nothing.
// Either way d points from a point of the grown start cell C to a point of an occupied box T, so
// d / |d| is a direction of the box T - C = [T.lo - C.hi, T.hi - C.lo], and fill_region() added
// every bin of every such box (direction_bins.cpp). So the ray's bin is set.
#include "rt/accel/exit_culling/exit_culling_table.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "rt/accel/parallel_parts.h"
#include "rt/accel/voxel/box.h"

namespace rt {

ExitCullingTable::ExitCullingTable(const Scene& scene, int resolution, int bins_per_side,
                                   int threads)
    : ExitCullingTable(culling_frame(scene), scene, resolution, bins_per_side, threads) {}

ExitCullingTable::ExitCullingTable(const CullingFrame& frame, const Scene& scene, int resolution,
                                   int bins_per_side, int threads)
    : cells_(frame, ReachSource{&scene, frame.rounding}, resolution,
             build_threads_for(threads, scene.polygons.size())),
      bins_(bins_per_side) {
    threads = build_threads_for(threads, scene.polygons.size());
    const int count = resolution * resolution * resolution;
    rows_.assign(static_cast<std::size_t>(count) * bins_.rows(), 0);
    // Each cell writes only its own rows.
    run_in_parts(static_cast<std::size_t>(count), std::min(threads, count),
                 [&](std::size_t begin, std::size_t end, int) {
                     for (std::size_t cell = begin; cell < end; ++cell) {
                         fill_region(static_cast<int>(cell));
                     }
                 });
    find_full_cells();
    add_all_grazing(ReachSource{&scene, frame.rounding}, threads);
    find_full_cells();
}

void ExitCullingTable::add_all_grazing(const ReachSource& reaches, int threads) {
    const int parts = std::max(threads, 1);
    // Part 0 writes the table itself; the others their own copies, or-ed in after.
    std::vector<std::vector<std::uint16_t>> copies(static_cast<std::size_t>(parts - 1),
                                                   std::vector<std::uint16_t>(rows_.size(), 0));
    run_in_parts(reaches.count(), parts, [&](std::size_t begin, std::size_t end, int part) {
        const std::span<std::uint16_t> rows =
            part == 0 ? std::span<std::uint16_t>(rows_)
                      : std::span<std::uint16_t>(copies[static_cast<std::size_t>(part - 1)]);
        std::vector<std::uint16_t> band(static_cast<std::size_t>(bins_.rows()));
        for (std::size_t id = begin; id < end; ++id) {
            add_grazing(reaches(id), band, rows);
        }
    });
    for (const std::vector<std::uint16_t>& copy : copies) {
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            rows_[i] |= copy[i];
        }
    }
}

void ExitCullingTable::find_full_cells() {
    const int count = static_cast<int>(rows_.size() / static_cast<std::size_t>(bins_.rows()));
    full_.resize(static_cast<std::size_t>(count));
    for (int cell = 0; cell < count; ++cell) {
        full_[static_cast<std::size_t>(cell)] = bins_.holds_all(region(cell));
    }
}

// A grazing hit is reported at Y within the polygon's grazing box. If the crossing X is ahead of
// the origin p, the tree pass has the direction already (X is in the polygon's plain reach). If
// X is behind p, then p lies between X and Y on a line within the grazing angle of the plane, so
// p is in the grazing box too: only cells meeting it need the grazing directions, and only
// those in the band of directions that see the polygon edge-on.
void ExitCullingTable::add_grazing(const PolygonReach& reach, std::vector<std::uint16_t>& band,
                                   std::span<std::uint16_t> rows) const {
    if (reach.grazing_box.empty()) {
        return;
    }
    // The band costs a sine per bin: found only for a cell that can still take bits. Most cells
    // a polygon's grazing box meets are full already (the polygon's own cells, for one).
    bool band_found = false;
    const double widen =
        1e-12 * std::max(reach.grazing_box.magnitude(), cells_.world().magnitude());
    int first[3];
    int last[3];
    cells_.cell_range(reach.grazing_box, cells_.margin(), first, last);
    const int r = cells_.resolution();
    for (int z = first[2]; z <= last[2]; ++z) {
        for (int y = first[1]; y <= last[1]; ++y) {
            for (int x = first[0]; x <= last[0]; ++x) {
                const int cell = x + r * (y + r * z);
                if (full_[static_cast<std::size_t>(cell)] != 0) {
                    continue;
                }
                const Box3 start = cells_.cell_box(x, y, z).grown(cells_.margin());
                const Box3 common = intersection(start, reach.grazing_box);
                if (common.empty() || !grazing_slab_meets_box(reach, common)) {
                    continue;
                }
                if (!band_found) {
                    bins_.band_of(reach.normal, reach.grazing_cosine, band);
                    band_found = true;
                }
                const std::span<std::uint16_t> set =
                    rows.subspan(static_cast<std::size_t>(cell) * bins_.rows(),
                                 static_cast<std::size_t>(bins_.rows()));
                bins_.add_directions_of(box_of_differences(reach.grazing_box, start, widen), set,
                                        band);
            }
        }
    }
}

void ExitCullingTable::fill_region(int cell) {
    const auto& tree = cells_.tree();
    if (tree.empty()) {
        return;
    }
    const Box3 start = cells_.cell_box(cell).grown(cells_.margin());
    const double widen = 1e-12 * std::max(start.magnitude(), cells_.world().magnitude());
    const std::span<std::uint16_t> set{rows_.data() + static_cast<std::size_t>(cell) * bins_.rows(),
                                       static_cast<std::size_t>(bins_.rows())};
    // Depth first; a group whose directions are all set already is skipped whole.
    std::vector<std::int32_t> stack{0};
    while (!stack.empty()) {
        const OccupiedCells::Node& node = tree[stack.back()];
        stack.pop_back();
        const Box3 towards = box_of_differences(node.box, start, widen);
        if (node.first_child < 0) {
            bins_.add_directions_of(towards, set);
        } else if (!bins_.holds_directions_of(towards, set)) {
            stack.push_back(node.first_child + 1);
            stack.push_back(node.first_child);
        }
    }
}

// The world clip from t = 0, with the reciprocals nothing_ahead() shares with bin_of().
int ExitCullingTable::entry_cell(const Ray& ray, const Vec3& inverse) const {
    const Box3& world = cells_.world();
    Interval inside;
    if (!clip_to_box(ray, inverse, world, {0.0, Box3::kInfinity}, inside)) {
        return -1;
    }
    Vec3 q = ray.at(inside.min);
    q = max_components(world.lo, min_components(world.hi, q));
    return cells_.cell_of(q);
}

bool ExitCullingTable::nothing_ahead(const Ray& ray, Interval t) const {
    // Rays leaving a surface start in a cell a polygon crosses, whose every bin is set: whatever
    // the rest of the test would say, they are passed on, so say it at once. (For an origin in
    // the world, entry_cell() below finds this same cell: the clip starts at t = 0.)
    if (starts_in_full_cell(ray.origin)) {
        return false;
    }
    if (!(t.min >= 0.0) || !is_finite(ray.origin) || !is_finite(ray.direction) ||
        (ray.direction.x == 0.0 && ray.direction.y == 0.0 && ray.direction.z == 0.0)) {
        return false;
    }
    if (cells_.tree().empty()) {
        return true;  // no polygon anywhere
    }
    // The far test on squares: no square root (an overflow to infinity still says "far").
    const Vec3 gap =
        max_components(cells_.frame().positions.lo - ray.origin,
                       max_components(Vec3{}, ray.origin - cells_.frame().positions.hi));
    const double far_limit = cells_.frame().far_limit;
    if (dot(gap, gap) > far_limit * far_limit) {
        return false;
    }
    // One division per axis, shared by the clip and the direction's bin.
    const Vec3 inverse{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    const int cell = entry_cell(ray, inverse);
    if (cell < 0) {
        return true;
    }
    return !bins_.contains(region(cell), bins_.bin_of(ray.direction, inverse));
}

double ExitCullingTable::empty_fraction() const {
    if (rows_.empty()) {
        return 0.0;
    }
    std::size_t set = 0;
    for (const std::uint16_t row : rows_) {
        set += static_cast<std::size_t>(std::popcount(row));
    }
    const double total = static_cast<double>(rows_.size()) * bins_.side();
    return 1.0 - static_cast<double>(set) / total;
}

std::size_t ExitCullingTable::memory_bytes() const {
    return rows_.capacity() * sizeof(std::uint16_t) + cells_.memory_bytes();
}

}  // namespace rt
