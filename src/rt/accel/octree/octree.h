// The octree intersection method (manual 1.3 and part three; scene header "1 depth").
#pragma once

#include <memory>
#include <vector>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"
#include "rt/accel/debug/describe_walk.h"
#include "rt/accel/octree/octree_top_table.h"
#include "rt/accel/octree/octree_tree.h"
#include "rt/accel/voxel/cell_packets.h"
#include "rt/accel/voxel/near_hit_rule.h"
#include "rt/accel/voxel/polygon_boxes.h"

namespace rt {

struct VoxelSearchParts;

class Octree : public Accelerator, public DescribesWalk {
public:
    /// Keeps a reference to the scene, which must outlive it. Uses settings.octree (its depth
    /// must be set), -of, -on and -tv; throws SettingError for a depth outside 0..20 or a tree that
    /// does not fit in 2^ol nodes.
    Octree(const Scene& scene, const AccelSettings& settings);
    std::string_view name() const override { return "octree"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;
    std::size_t memory_bytes() const override {
        return tree_.memory_bytes() + walk_nodes_.capacity() * sizeof(OctreeNode) +
               top_.entry.capacity() * sizeof(OctreeTopTable::Entry) + boxes_.memory_bytes() +
               packets_.memory_bytes();
    }

    std::string describe_walk(const Ray& ray, Interval t) const override;

    const OctreeTree& tree() const { return tree_; }

private:
    const Scene& scene_;
    OctreeTree tree_;
    WalkRules rules_;
    PolygonBoxes boxes_;
    CellPackets packets_;  ///< by node number (none for interior nodes)
    /// The tree's nodes, each leaf holding where its packets lie instead of its ids (first
    /// block, block count), for the queries' walk: it then reaches a leaf's packets straight
    /// from the node it has just read, not through packets_' table indexed by node, whose
    /// entries are scattered reads of their own on a big tree.
    std::vector<OctreeNode> walk_nodes_;
    /// Where the walk's descents near the top of the tree start (octree_top_table.h).
    OctreeTopTable top_;
    /// Whether the walk finds each next leaf before visiting the current one, to prefetch it:
    /// only for a structure too big to stay in the cache (kLookAheadBytes, octree.cpp).
    bool look_ahead_ = true;

    VoxelSearchParts search_parts() const;
    template <class Visit>
    void walk(const Ray& ray, const Vec3& inverse, Interval inside, Visit& visit) const;
};

std::unique_ptr<Accelerator> make_octree(const Scene& scene, const AccelSettings& settings);

}  // namespace rt
