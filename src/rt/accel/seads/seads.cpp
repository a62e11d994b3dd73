#include "rt/accel/seads/seads.h"

#include <limits>

#include "rt/accel/seads/seads_walk.h"
#include "rt/accel/voxel/voxel_queries.h"
#include "rt/core/prefetch.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rt {

namespace {

// The queries' visit, told each voxel's packets (none for a run of empty voxels).
template <class Visit>
auto with_packets(Visit& visit, const CellPackets& packets) {
    return [&visit, &packets](std::size_t voxel, double t_exit, const int*) {
        return visit(voxel == kNoSeadsVoxel ? CellView{} : packets.cell(voxel), t_exit);
    };
}

// Two steps ahead: the next voxel's packets, whose entry in the cell table is read (a load, not a
// prefetch: the step before asked for it), and the entry of the voxel after. The entry alone, one
// step ahead, left a random ray waiting on each voxel's first packet (docs/accelerators.md). The
// table's address is read once, before the branches: read in each, GCC 12 dropped both prefetches.
auto packets_ahead(const CellPackets& packets) {
    return [cells = &packets](std::size_t next, std::size_t after) {
        const std::uint32_t* table = cells->cell_table();
        if (after != SeadsCursor::kNoVoxelAhead) {
            prefetch(table + after);
        }
        if (next != SeadsCursor::kNoVoxelAhead) {
            cells->prefetch_blocks(table[next]);
        }
    };
}

}  // namespace

Seads::Seads(const Scene& scene, const AccelSettings& settings)
    : scene_(scene),
      grid_(build_seads_grid(scene, settings.seads_resolution.value_or(0), settings.no_fudge)),
      rules_(WalkRules::from(settings)),
      boxes_(scene, voxel_fudge(grid_.world, false)),
      packets_(
          scene, grid_.offsets.size() - 1, grid_.bounds_slots,
          [&](std::size_t v) { return grid_.voxel(v); }, static_cast<int>(settings.build_threads)) {
}

// -tv counts every fruitless voxel, so it needs the walk to visit each one.
EmptySpace Seads::empty_space() const {
    return rules_.fruitless_voxel_limit == std::numeric_limits<std::uint64_t>::max()
               ? EmptySpace::Leap
               : EmptySpace::VisitEach;
}

VoxelSearchParts Seads::search_parts() const {
    return {scene_, boxes_, grid_.world, grid_.bounds_slots, rules_, packets_};
}

std::optional<Hit> Seads::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_closest_hit(
        search_parts(), ray, t, counters, [&](Interval inside, const Vec3& inverse, auto&& visit) {
            walk_seads_voxels(grid_, ray, inverse, inside, with_packets(visit, packets_),
                              empty_space(), packets_ahead(packets_));
        });
}

bool Seads::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_occluded(
        search_parts(), ray, t, counters, [&](Interval inside, const Vec3& inverse, auto&& visit) {
            walk_seads_voxels(grid_, ray, inverse, inside, with_packets(visit, packets_),
                              empty_space(), packets_ahead(packets_));
        });
}

std::string Seads::describe_walk(const Ray& ray, Interval t) const {
    std::string lines;
    walk_seads(
        grid_, ray, t,
        [&](std::span<const std::uint32_t> polygons, double t_exit, const int* voxel) {
            lines += fmt::format("  voxel ({}, {}, {}) leaves at t {}: polygons {}\n", voxel[0],
                                 voxel[1], voxel[2], t_exit, fmt::join(polygons, " "));
            return false;
        },
        EmptySpace::VisitEach);
    return lines;
}

std::unique_ptr<Accelerator> make_seads(const Scene& scene, const AccelSettings& settings) {
    return std::make_unique<Seads>(scene, settings);
}

}  // namespace rt
