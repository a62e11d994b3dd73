#include "rt/accel/bvh/bvh.h"

#include "rt/accel/bvh/bvh_builder.h"
#include "rt/accel/bvh/collapse.h"
#include "rt/accel/bvh/polygon_references.h"

namespace rt {

namespace {

// Past this many leaves a line crosses, the first leaf's records are not asked for. A line
// crosses 2.4-2.6 of the lab's spheres' leaves (their camera rays ran 4-13 % slower without the
// records), 0.8 of twocubes', and 5.1, 11.2, 24.4 and 52.7 of the 1k, 10k, 100k and 1M soups'.
constexpr double kFirstLeafRecordsMostLeaves = 8.0;

}  // namespace

Bvh::Bvh(const Scene& scene, const BvhSettings& settings) : scene_(scene) {
    bvh::PolygonReferences refs = bvh::make_polygon_references(scene, settings.build_threads);
    unbounded_ = std::move(refs.unbounded);
    tree_ = bvh::build_hierarchy(scene, refs, settings.build_threads);
    bvh::collapse_to_wide(tree_, settings.build_threads);
    // The first leaf's polygon records are asked for on the bet that the first leaf a ray enters
    // holds its hit: so it does on a surface, where a line crosses two or three leaves, but not
    // where it crosses dozens, as in a soup of long triangles, and there the records' sixteen
    // misses only hold up the walk's own (docs/lab/ray-cost-2026-12-08.md).
    tree_.first_leaf_records = bvh::leaves_a_line_crosses(tree_) <= kFirstLeafRecordsMostLeaves;
}

std::size_t Bvh::memory_bytes() const {
    return sizeof(*this) + tree_.nodes.capacity() * sizeof(bvh::Node) +
           tree_.wide.capacity() * sizeof(bvh::WideNode) +
           tree_.packets.capacity() * sizeof(bvh::TrianglePacket) +
           unbounded_.capacity() * sizeof(std::uint32_t);
}

std::unique_ptr<Accelerator> make_bvh(const Scene& scene, const BvhSettings& settings) {
    return std::make_unique<Bvh>(scene, settings);
}

}  // namespace rt
