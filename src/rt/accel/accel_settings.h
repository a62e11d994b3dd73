// Which intersection method to build and how (manual part three, 2.2 header numbers 3 and 4, and
// the Appendix's -o and -t switches). Filled from the scene header and the switches by the app.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

enum class AccelKind { BruteForce, Octree, Seads, Bvh, Embree };

/// "brute", "octree", "seads", "bvh", "embree": the names --accel takes and the lab prints.
std::string_view accel_kind_name(AccelKind kind);
std::optional<AccelKind> accel_kind_from_name(std::string_view name);

/// Voxel sizes for a scene of this many polygons when nothing names one, measured best on cube
/// spheres (bench/voxel): about one SEADS voxel a side per cube root of the count (finer grids
/// walk more empty voxels than they save tests), and an octree depth of log2(count) / 2.5.
int suggested_seads_resolution(std::size_t polygons);
int suggested_octree_depth(std::size_t polygons);

struct AccelSettings {
    AccelKind kind = AccelKind::BruteForce;
    int octree_depth = 0;                       ///< header's octr, or -od
    int seads_resolution = 0;                   ///< header's sptncde (> 1): voxels a side
    std::optional<int> octlist_power;           ///< -ol: octree storage 2^n
    std::optional<int> seed_size_power;         ///< -ss: seed size 2^n
    bool new_fillplane = false;                 ///< -op
    bool accept_near_hits = false;              ///< -on
    bool no_fudge = false;                      ///< -of
    std::optional<int> terminate_after_voxels;  ///< -tv
    /// -dof: told, level by level, what the -op fill did (may be empty).
    std::function<void(const std::string&)> fill_trace;
};

}  // namespace rt
