// -doo: "Output the octree to octree.lst" (manual, Appendix), a text listing of the tree: one line
// per node, depth first, indented by level, leaves with their polygon ids.
#pragma once

#include <ostream>

#include "rt/accel/octree/octree_tree.h"

namespace rt {

void write_octree_listing(const OctreeTree& tree, std::ostream& out);

}  // namespace rt
