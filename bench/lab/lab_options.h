// The lab's command line: which meshes, sizes and intersection methods, and where to write.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rt/accel/accel_settings.h"

#include <CLI/CLI.hpp>

namespace rt::lab {

struct LabOptions {
    std::vector<std::uint32_t> sizes{1000, 10000, 100000, 1000000};
    std::vector<std::string> meshes{"sphere", "soup", "twocubes"};
    std::vector<AccelKind> accels{AccelKind::BruteForce, AccelKind::Octree, AccelKind::Seads,
                                  AccelKind::Bvh, AccelKind::Embree};
    /// Every method measured this many times on each mesh, in turn forward and backward.
    unsigned rounds = 1;
    unsigned threads = 0;            ///< for the all-cores runs; 0: every hardware thread
    double seconds_per_run = 0.3;    ///< each measurement repeats its rays at least this long
    double brute_force_tests = 2e8;  ///< ray-polygon tests brute force may spend per measurement
    /// Brute force is skipped on bigger meshes: its subsample would be a handful of rays.
    std::uint64_t brute_force_largest = 1000000;
    std::string csv_file;
    std::string svg_file;
    std::string time_svg_file;     ///< time per ray against triangles, log-log
    int seads_side = 0;            ///< SEADS voxels a side; 0: suggested_seads_resolution
    int octree_depth = 0;          ///< octree depth; 0: suggested_octree_depth
    std::string source_dir = ".";  ///< where scenes/twocubes.scn is
    /// The CPU the one-thread measurements run on; kNoPin: wherever the system puts them.
    static constexpr int kNoPin = -1;
    int pin_cpu = kNoPin;
};

/// Declares the lab's options on app, writing into options. They take effect in command-line
/// order, so a --sizes or --seconds after --quick overrides it, and one before it does not.
void add_lab_options(CLI::App& app, LabOptions& options);

}  // namespace rt::lab
