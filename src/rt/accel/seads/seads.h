// SEADS, the "spatially enumerated auxiliary data structure" (manual 2.2, part three): a uniform
// grid of voxels walked along the ray by a 3D-DDA (Fujimoto's ARTS; Amanatides and Woo).
#pragma once

#include <memory>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"
#include "rt/accel/debug/describe_walk.h"
#include "rt/accel/seads/seads_grid.h"
#include "rt/accel/seads/seads_walk.h"
#include "rt/accel/voxel/cell_packets.h"
#include "rt/accel/voxel/near_hit_rule.h"
#include "rt/accel/voxel/polygon_boxes.h"

namespace rt {

struct VoxelSearchParts;

class Seads : public Accelerator, public DescribesWalk {
public:
    /// Keeps a reference to the scene, which must outlive it. Uses settings.seads_resolution
    /// voxels a side, -of, -on and -tv.
    Seads(const Scene& scene, const AccelSettings& settings);
    std::string_view name() const override { return "SEADS"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;
    std::size_t memory_bytes() const override {
        return grid_.memory_bytes() + boxes_.memory_bytes() + packets_.memory_bytes();
    }

    std::string describe_walk(const Ray& ray, Interval t) const override;

    const SeadsGrid& grid() const { return grid_; }

private:
    const Scene& scene_;
    SeadsGrid grid_;
    WalkRules rules_;
    PolygonBoxes boxes_;
    CellPackets packets_;  ///< by voxel number

    EmptySpace empty_space() const;
    VoxelSearchParts search_parts() const;
};

std::unique_ptr<Accelerator> make_seads(const Scene& scene, const AccelSettings& settings);

}  // namespace rt
