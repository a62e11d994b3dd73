#include "rt/accel/bvh/bvh.h"

#include "rt/accel/bvh/bvh_builder.h"
#include "rt/accel/bvh/collapse.h"
#include "rt/accel/bvh/polygon_references.h"

namespace rt {

Bvh::Bvh(const Scene& scene, const BvhSettings& settings) : scene_(scene) {
    bvh::PolygonReferences refs = bvh::make_polygon_references(scene, settings.build_threads);
    unbounded_ = std::move(refs.unbounded);
    tree_ = bvh::build_hierarchy(scene, refs, settings.build_threads);
    bvh::collapse_to_wide(tree_, settings.build_threads);
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
