// Collapses the builder's 4-wide tree into 8-wide nodes: fewer levels, so fewer dependent cache
// misses per ray.
#pragma once

#include "rt/accel/bvh/bvh_layout.h"

namespace rt::bvh {

/// Fills tree.wide from tree.nodes, renumbers tree.root into it, and frees tree.nodes. `threads`
/// (0: one per hardware thread) share the work; the result is the same for any count.
void collapse_to_wide(Hierarchy& tree, unsigned threads = 1);

}  // namespace rt::bvh
