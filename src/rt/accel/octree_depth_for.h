// The octree depth a scene gets when neither its header nor -od names one.
#pragma once

#include "rt/scene/scene.h"

namespace rt {

/// The depth at which the scene's occupied deepest cells would hold about 12 polygons each
/// (counting each polygon in the cell of its centre). How the count of occupied cells grows with
/// depth is measured on the scene: about 4 times a level for polygons on a surface, 8 for polygons
/// filling a volume (a soup). Scenes of fewer than 4096 polygons, too few to measure that on, get
/// suggested_octree_depth(polygons).
int octree_depth_for(const Scene& scene);

/// The same from measured counts: `polygons` in all, and of the cells of two lattice levels
/// (2^coarse and 2^(coarse + 2) a side) `occupied_coarse` and `occupied_fine` hold one.
int octree_depth_from_occupancy(std::size_t polygons, int coarse, std::size_t occupied_coarse,
                                std::size_t occupied_fine);

}  // namespace rt
