// Builds the 4-wide BVH top-down: binned SAH splits, each node taking the up to four largest
// ranges the splits make, big subtrees built on their own threads.
#pragma once

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/polygon_references.h"

namespace rt::bvh {

/// Reorders refs.bounded. `threads` 0 means one per hardware thread.
Hierarchy build_hierarchy(const Scene& scene, PolygonReferences& refs, unsigned threads = 0);

}  // namespace rt::bvh
