// Which intersection method to build and how (manual part three, 2.2 header numbers 3 and 4, and
// the Appendix's -o, -t and -d switches). The program's switches write them; what they leave
// unset, the scene header decides (method_for_scene in make_accelerator.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

enum class AccelKind { BruteForce, Octree, Seads, Bvh, Embree };

/// "brute", "octree", "seads", "bvh", "embree": the names --accel takes and the lab prints.
std::string_view accel_kind_name(AccelKind kind);
std::optional<AccelKind> accel_kind_from_name(std::string_view name);

/// Voxel sizes for a scene of this many polygons when nothing names one, measured best in the lab
/// and on cube spheres (bench/voxel): 0.7 SEADS voxels a side per cube root of the count (finer
/// grids walk more empty voxels, and file a large polygon in more of them, than they save tests),
/// and an octree depth of (log2(count) - 6) / 2, so that 4^depth is about count / 64: a surface's
/// deepest leaves then hold a few dozen polygons, which their packets and bounds test cheaply.
int suggested_seads_resolution(std::size_t polygons);
int suggested_octree_depth(std::size_t polygons);

/// How to build the octree: its depth and node pool (-od, -ol, -ss), its fill (-op, -dof).
struct OctreeBuildSettings {
    std::optional<int> depth;            ///< -od; none: method_for_scene() decides
    std::optional<int> octlist_power;    ///< -ol: at most 2^n nodes
    std::optional<int> seed_size_power;  ///< -ss: 2^n nodes allocated at first
    bool level_order = false;            ///< -op, the "new fill-plane": a level at a time
    /// Threads for the default fill's subtrees (0: one a core); the tree is the same for any.
    /// The Octree sets it from AccelSettings::build_threads.
    unsigned threads = 0;
    std::function<void(const std::string&)> fill_trace;  ///< -dof: the -op fill, level by level
};

struct AccelSettings {
    std::optional<AccelKind> kind;              ///< --accel; none: the scene header's method
    std::optional<int> seads_resolution;        ///< voxels a side; none: method_for_scene() decides
    OctreeBuildSettings octree;                 ///< -od -ol -ss -op -dof
    bool accept_near_hits = false;              ///< -on
    bool no_fudge = false;                      ///< -of
    std::optional<int> terminate_after_voxels;  ///< -tv
    /// --threads: the threads that build the method (and exit culling around it), 0 for one a
    /// core. Every build gives the same structure for any number.
    unsigned build_threads = 0;
};

/// The whole stack of accelerator_stack.h: the method, and the layers around it.
struct AcceleratorStackSettings {
    AccelSettings method;      ///< which method, and how (header, --accel, -o switches)
    bool exit_culling = true;  ///< false with -De
    /// The most rays the render sends from the eye (its pixels' samples and centre probes), or 0
    /// when not known (-r). Exit culling is left out of a scene with more polygons than that:
    /// its table cannot pay for itself (kept with -de, which asks to check it).
    std::uint64_t most_eye_rays = 0;
    bool check_exit_culling = false;  ///< -de: re-trace every culled ray
    bool zbuffer_first_hits = false;  ///< --zbuffer
    bool strike_check = false;        ///< -ds
    bool strike_print = false;        ///< -dsp: print each difference (implies the check)
    bool strike_voxels = false;       ///< -dso: ... with the voxels walked (implies it too)
    bool log_intersections = false;   ///< -dl
    bool trace_fill = false;          ///< -dof: the octree fill traces to the stack's trace sink
    std::optional<std::filesystem::path> octree_listing;  ///< -doo: write the octree there
};

}  // namespace rt
