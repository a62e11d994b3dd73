// Builds the intersection method the settings name.
#pragma once

#include <memory>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"

namespace rt {

/// The settings with what they leave unset decided for this scene: the method the header names
/// (0 0 brute force, 1 depth octree, N 0 SEADS), its octree depth or SEADS voxels a side, and for
/// a method the header does not name, the sizes suggested for the scene: SEADS's for its polygon
/// count, and when the method is the octree, octree_depth_for(scene). The octree depth is left
/// unset when neither the header nor the settings name an octree.
AccelSettings method_for_scene(const Scene& scene, AccelSettings settings);

/// Builds the method of method_for_scene(scene, asked). The scene must outlive the result.
/// Throws NotImplementedError for a method not built in (an Embree backend without Embree) and
/// SettingError for settings it cannot honour.
std::unique_ptr<Accelerator> make_accelerator(const Scene& scene, const AccelSettings& asked);

}  // namespace rt
