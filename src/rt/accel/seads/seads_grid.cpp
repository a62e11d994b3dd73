#include "rt/accel/seads/seads_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "rt/accel/voxel/polygon_box_overlap.h"
#include "rt/accel/voxel/voxel_bounds.h"
#include "rt/core/error.h"
#include "rt/core/huge_pages.h"

namespace rt {

namespace {

void check_side(int side) {
    if (side < 1) {
        throw SettingError("SEADS voxels a side",
                           "SEADS needs at least 1 voxel a side, not " + std::to_string(side));
    }
    const auto n = static_cast<std::uint64_t>(side);
    if (n > 1024 || n * n * n > kMaxSeadsVoxels) {
        throw SettingError("SEADS voxels a side",
                           "SEADS with " + std::to_string(side) + " voxels a side would need " +
                               std::to_string(n * n * n) + " voxels; at most " +
                               std::to_string(kMaxSeadsVoxels) +
                               " are built (322 a side): use fewer SEADS voxels a side");
    }
}

// The voxels along one axis that the range [lo, hi] may touch.
std::pair<int, int> voxel_range(const SeadsGrid& grid, int axis, double lo, double hi) {
    const double start = grid.world.lo[axis];
    const double size = grid.voxel_size[axis];
    auto cell = [&](double x) {
        const double c = std::floor((x - start) / size);
        return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(grid.side - 1)));
    };
    return {cell(lo), cell(hi)};
}

bool holds_a_corner(const Scene& scene, std::uint32_t id, const Box3& box) {
    const Polygon& p = scene.polygons[id];
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        if (box.contains(scene.corner_position(p, k))) {
            return true;
        }
    }
    return false;
}

using VoxelAndPolygon = std::pair<std::uint32_t, std::uint32_t>;

void file_polygon(const Scene& scene, const SeadsGrid& grid, double fudge, std::uint32_t id,
                  std::vector<VoxelAndPolygon>& out) {
    const Box3 bounds = polygon_bounds(scene, id).grown(fudge);
    const auto [x0, x1] = voxel_range(grid, 0, bounds.lo.x, bounds.hi.x);
    const auto [y0, y1] = voxel_range(grid, 1, bounds.lo.y, bounds.hi.y);
    const auto [z0, z1] = voxel_range(grid, 2, bounds.lo.z, bounds.hi.z);
    if (x0 == x1 && y0 == y1 && z0 == z1) {
        // Small polygons, the common case, need no overlap test.
        out.emplace_back(static_cast<std::uint32_t>(grid.index(x0, y0, z0)), id);
        return;
    }
    for (int z = z0; z <= z1; ++z) {
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                // A voxel holding one of the corners certainly touches the polygon; only the
                // others need the exact test.
                const Box3 box = grid.voxel_box(x, y, z).grown(fudge);
                if (holds_a_corner(scene, id, box) || polygon_overlaps_box(scene, id, box)) {
                    out.emplace_back(static_cast<std::uint32_t>(grid.index(x, y, z)), id);
                }
            }
        }
    }
}

// One more than the least clearance among the 13 neighbours of (x, y, z) that come before it in
// a raster pass (pass = +1, the usual order) or after it (pass = -1): the previous plane's 9, the
// previous row's 3 in this plane, the previous voxel in this row.
int clearance_from_earlier_neighbours(const SeadsGrid& grid, int x, int y, int z, int pass) {
    const int n = grid.side;
    int best = 255;
    for (int dz = 0; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const bool before = dz == 1 || dy == 1 || (dy == 0 && dx == 1);
                const int nx = x - pass * dx;
                const int ny = y - pass * dy;
                const int nz = z - pass * dz;
                if (!before || nx < 0 || ny < 0 || nz < 0 || nx >= n || ny >= n || nz >= n) {
                    continue;
                }
                best = std::min(best, grid.clearance[grid.index(nx, ny, nz)] + 1);
            }
        }
    }
    return best;
}

// The chessboard distance transform in two raster passes (Rosenfeld and Pfaltz): forward, each
// voxel takes one more than the least of its 13 neighbours already passed; backward, of the other
// 13. With unit steps to all 26 neighbours the result is exact for the chessboard distance.
void fill_clearance(SeadsGrid& grid) {
    const int n = grid.side;
    const std::size_t voxels = static_cast<std::size_t>(n) * n * n;
    reserve_huge(grid.clearance, voxels);
    grid.clearance.assign(voxels, 255);
    for (std::size_t v = 0; v < voxels; ++v) {
        if (grid.offsets[v] != grid.offsets[v + 1]) {
            grid.clearance[v] = 0;
        }
    }
    // Raster order is index order (x fastest, then y, then z); the backward pass runs it in
    // reverse.
    for (const int pass : {1, -1}) {
        for (std::size_t i = 0; i < voxels; ++i) {
            const std::size_t v = pass > 0 ? i : voxels - 1 - i;
            if (grid.clearance[v] == 0) {
                continue;
            }
            const auto x = static_cast<int>(v % n);
            const auto y = static_cast<int>((v / n) % n);
            const auto z = static_cast<int>(v / (static_cast<std::size_t>(n) * n));
            grid.clearance[v] = static_cast<std::uint8_t>(std::min<int>(
                grid.clearance[v], clearance_from_earlier_neighbours(grid, x, y, z, pass)));
        }
    }
}

// Rewrites the voxels' id lists (`ids`, indexed by grid.offsets) with each occupied voxel's bounds
// in front of its ids (voxel_bounds.h).
void lay_out_with_bounds(const Scene& scene, SeadsGrid& grid, const std::vector<std::uint32_t>& ids,
                         std::size_t occupied) {
    const double growth = voxel_fudge(grid.world, false);
    const std::vector<float> boxes = grown_polygon_boxes(scene, growth);
    const std::size_t voxels = grid.offsets.size() - 1;
    std::vector<std::uint32_t> laid_out;
    laid_out.reserve(ids.size() + kVoxelBoundsSlots * occupied);
    std::vector<std::uint32_t> offsets(voxels + 1, 0);
    const int n = grid.side;
    for (int z = 0; z < n; ++z) {
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const std::size_t v = grid.index(x, y, z);
                offsets[v] = static_cast<std::uint32_t>(laid_out.size());
                const std::uint32_t begin = grid.offsets[v];
                const std::uint32_t end = grid.offsets[v + 1];
                if (begin == end) {
                    continue;
                }
                append_voxel_bounds(boxes, {ids.data() + begin, ids.data() + end},
                                    grid.voxel_box(x, y, z), growth, laid_out);
                laid_out.insert(laid_out.end(), ids.begin() + begin, ids.begin() + end);
            }
        }
    }
    offsets[voxels] = static_cast<std::uint32_t>(laid_out.size());
    grid.offsets = std::move(offsets);
    grid.polygons = std::move(laid_out);
    grid.bounds_slots = kVoxelBoundsSlots;
}

}  // namespace

Box3 SeadsGrid::voxel_box(int x, int y, int z) const {
    const Vec3 lo{world.lo.x + x * voxel_size.x, world.lo.y + y * voxel_size.y,
                  world.lo.z + z * voxel_size.z};
    // The last voxel ends exactly at the world's face, whatever the rounding of lo + n * size.
    const Vec3 hi{x + 1 == side ? world.hi.x : world.lo.x + (x + 1) * voxel_size.x,
                  y + 1 == side ? world.hi.y : world.lo.y + (y + 1) * voxel_size.y,
                  z + 1 == side ? world.hi.z : world.lo.z + (z + 1) * voxel_size.z};
    return {lo, hi};
}

SeadsGrid build_seads_grid(const Scene& scene, int side, bool no_fudge) {
    check_side(side);
    SeadsGrid grid;
    grid.side = side;
    grid.world = world_box(scene, false);
    grid.voxel_size = grid.world.extent() / static_cast<double>(side);
    grid.per_voxel = {1.0 / grid.voxel_size.x, 1.0 / grid.voxel_size.y, 1.0 / grid.voxel_size.z};
    const double fudge = voxel_fudge(grid.world, no_fudge);

    // One pass collects (voxel, polygon) pairs in polygon order; a counting sort by voxel then
    // lays them out, so each voxel's ids stay ascending.
    std::vector<VoxelAndPolygon> pairs;
    pairs.reserve(scene.polygons.size() + scene.polygons.size() / 2);
    const auto count = static_cast<std::uint32_t>(scene.polygons.size());
    for (std::uint32_t id = 0; id < count; ++id) {
        file_polygon(scene, grid, fudge, id, pairs);
    }
    if (pairs.size() >= std::numeric_limits<std::uint32_t>::max()) {
        throw SettingError("SEADS voxels a side",
                           "SEADS: more than 2^32 polygon references: use fewer SEADS voxels a "
                           "side");
    }

    // Counts, then running ends; filling backwards moves each end down to its voxel's start.
    const std::size_t voxels = static_cast<std::size_t>(side) * side * side;
    grid.offsets.assign(voxels + 1, 0);
    for (const auto& [voxel, id] : pairs) {
        ++grid.offsets[voxel];
    }
    for (std::size_t v = 1; v <= voxels; ++v) {
        grid.offsets[v] += grid.offsets[v - 1];
    }
    std::vector<std::uint32_t> ids(pairs.size());
    for (auto it = pairs.rbegin(); it != pairs.rend(); ++it) {
        ids[--grid.offsets[it->first]] = it->second;
    }
    std::size_t occupied = 0;
    for (std::size_t v = 0; v < voxels; ++v) {
        occupied += grid.offsets[v] != grid.offsets[v + 1] ? 1 : 0;
    }
    // (Bounds only where the ids and bounds together stay below 2^32 slots.)
    const std::uint64_t slots = ids.size() + std::uint64_t{kVoxelBoundsSlots} * occupied;
    if (worth_voxel_bounds(ids.size(), occupied) &&
        slots < std::numeric_limits<std::uint32_t>::max()) {
        lay_out_with_bounds(scene, grid, ids, occupied);
    } else {
        grid.polygons = std::move(ids);
    }
    fill_clearance(grid);
    return grid;
}

}  // namespace rt
