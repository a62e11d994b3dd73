// The lines of the wireframe, in the scene's space: every polygon's edges, the "little green
// normals" of the scene header's normallength (manual 2.2), and the octree's boxes (-oo).
#pragma once

#include <vector>

#include "rt/accel/octree/octree_tree.h"
#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

struct WireSegment {
    Vec3 from;
    Vec3 to;
};

/// Each polygon's edges, corner to corner around its loop (an edge two polygons share is listed
/// by both).
std::vector<WireSegment> polygon_edges(const Scene& scene);

/// For each polygon, a line from its centre (the mean of its corners, as lghtick 2 takes it)
/// `length` scene units along its outward normal; none when length is 0. A negative length
/// points the lines inward.
std::vector<WireSegment> polygon_normals(const Scene& scene, double length);

/// The twelve edges of every leaf of the octree, empty leaves too: together they show every
/// split the build made (a node's box is the union of its children's).
std::vector<WireSegment> octree_leaf_edges(const OctreeTree& tree);

}  // namespace rt
