// What the scene benchmark prints, and the CSV row it can append.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render_timing.h"
#include "replay_timing.h"

namespace rt::bench {

struct BenchRun {
    std::string scene;        ///< as given on the command line
    std::string accelerator;  ///< its name()
    std::size_t polygons = 0;
    int width = 0;  ///< of the rendered window
    int height = 0;
    double load_seconds = 0.0;
    double build_seconds = 0.0;
    RenderTimes renders;
    /// --replay: the rays of one recorded render, and each method's replays of them.
    std::uint64_t recorded_rays = 0;
    std::vector<ReplayTimes> replays;
};

/// A few human-readable lines: the setup, then median and minimum per render and rays per second.
std::string describe(const BenchRun& run);

/// Appends one row to `file`, writing the header line first if the file is new or empty.
/// Throws rt::IoError if it cannot be written.
void append_csv_row(const std::filesystem::path& file, const BenchRun& run);

}  // namespace rt::bench
