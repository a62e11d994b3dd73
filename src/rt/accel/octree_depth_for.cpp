#include "rt/accel/octree_depth_for.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rt/accel/accel_settings.h"

namespace rt {

namespace {

// Polygons per occupied deepest cell the depth aims at, each counted in the cell of its centre
// (a leaf also holds the polygons reaching in from its neighbours). With cell packets and bounds
// (voxel/) a leaf of a few dozen polygons tests cheaply, and each level less saves steps and
// memory; 12 gave the depths measured best (docs/lab/octree-depth-2026-12-04.md).
constexpr double kPolygonsPerCell = 12.0;
// At most this many polygons are looked at (every k-th), so the measure costs little on huge
// scenes; the finer level has at most an eighth as many cells, so it is well sampled.
constexpr std::size_t kMostSamples = std::size_t{1} << 16;
constexpr std::size_t kFewestPolygons = 4096;

// The distinct cells of a lattice of 2^level a side over `box` that hold one of the points.
std::size_t occupied_cells(const std::vector<Vec3>& points, const Box3& box, int level) {
    const std::size_t side = std::size_t{1} << level;
    std::vector<std::uint8_t> seen(side * side * side, 0);
    std::size_t occupied = 0;
    for (const Vec3& p : points) {
        std::size_t index = 0;
        for (int a = 0; a < 3; ++a) {
            const double extent = box.hi[a] - box.lo[a];
            const double along = extent > 0.0 ? (p[a] - box.lo[a]) / extent : 0.0;
            const double cell = std::clamp(std::floor(along * static_cast<double>(side)), 0.0,
                                           static_cast<double>(side - 1));
            index = index * side + static_cast<std::size_t>(cell);
        }
        if (seen[index] == 0) {
            seen[index] = 1;
            ++occupied;
        }
    }
    return occupied;
}

}  // namespace

int octree_depth_from_occupancy(std::size_t polygons, int coarse, std::size_t occupied_coarse,
                                std::size_t occupied_fine) {
    // Cells occupied grow as 2^(dimension * level): 2 for a surface, 3 for a volume.
    const double growth = static_cast<double>(std::max(occupied_fine, std::size_t{1})) /
                          static_cast<double>(std::max(occupied_coarse, std::size_t{1}));
    const double dimension = std::clamp(std::log2(growth) / 2.0, 1.0, 3.0);
    const double per_cell_at_coarse =
        static_cast<double>(polygons) /
        static_cast<double>(std::max(occupied_coarse, std::size_t{1}));
    const double depth =
        coarse + std::log2(std::max(per_cell_at_coarse / kPolygonsPerCell, 1.0)) / dimension;
    return static_cast<int>(std::clamp(std::lround(depth), 1L, 20L));
}

int octree_depth_for(const Scene& scene) {
    const std::size_t polygons = scene.polygons.size();
    if (polygons < kFewestPolygons) {
        return suggested_octree_depth(polygons);
    }
    const std::size_t stride = (polygons + kMostSamples - 1) / kMostSamples;
    std::vector<Vec3> centres;
    centres.reserve(polygons / stride + 1);
    for (std::size_t i = 0; i < polygons; i += stride) {
        const Polygon& p = scene.polygons[i];
        Vec3 sum{0.0, 0.0, 0.0};
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            sum = sum + scene.corner_position(p, k);
        }
        centres.push_back(sum * (1.0 / static_cast<double>(p.corner_count)));
    }
    // The finest level with at least 8 samples a cell (3 or 4, as 4096 to 65,536 polygons are
    // sampled), and the one two levels above it.
    const double samples = static_cast<double>(centres.size());
    const int fine = std::max(3, static_cast<int>(std::floor(std::log2(samples / 8.0) / 3.0)));
    const int coarse = fine - 2;
    // The centres' own box: reading every position for the scene's box would cost more than
    // the rest of the measure.
    Box3 box;
    for (const Vec3& c : centres) {
        box.add(c);
    }
    return octree_depth_from_occupancy(polygons, coarse, occupied_cells(centres, box, coarse),
                                       occupied_cells(centres, box, fine));
}

}  // namespace rt
