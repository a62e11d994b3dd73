// The BVH's tree does not depend on how many threads build it: references made on runs of
// polygons, big ranges binned in parallel, the sides near the top split at once, subtrees spawned
// and appended, packets written by runs of leaves, wide nodes collapsed by parts. Every node and
// packet is compared byte for byte, on a mesh big enough to take each of those paths.
#include <cstdint>
#include <cstring>

#include "rt/accel/bvh/bvh_builder.h"
#include "rt/accel/bvh/collapse.h"
#include "rt/accel/bvh/polygon_references.h"

#include <gtest/gtest.h>

#include "support/meshes/generated_meshes.h"

namespace rt::bvh {
namespace {

Hierarchy build(const Scene& scene, unsigned threads) {
    PolygonReferences refs = make_polygon_references(scene, threads);
    Hierarchy tree = build_hierarchy(scene, refs, threads);
    collapse_to_wide(tree, threads);
    return tree;
}

template <class Array>
bool same_bytes(const Array& a, const Array& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

TEST(BvhBuildThreads, TheTreeIsTheSameForAnyThreadCount) {
    // Over 2^18 references (binned in parallel), both sides of the root over 2^16 (split at
    // once), subtrees over 4096 (spawned), over 4096 leaves a run (packets by several threads).
    const Scene scene = test::make_triangle_soup(300000, 7);
    const Hierarchy one = build(scene, 1);
    ASSERT_GT(one.wide.size(), 1000u);
    for (const unsigned threads : {2u, 3u, 8u}) {
        SCOPED_TRACE(threads);
        const Hierarchy many = build(scene, threads);
        EXPECT_EQ(many.root, one.root);
        EXPECT_EQ(many.scale, one.scale);
        EXPECT_TRUE(same_bytes(many.wide, one.wide));
        EXPECT_TRUE(same_bytes(many.packets, one.packets));
    }
}

}  // namespace
}  // namespace rt::bvh
