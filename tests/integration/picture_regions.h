// Pictures rendered by the rt program, measured region by region: what the switch-effect table
// (switch_effect_table.h) asserts about a switch is where its picture differs from the base
// picture, and how.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rt/core/rgb.h"
#include "rt/image/image8.h"

namespace rt::test {

/// A rectangle of the picture, inclusive, in pixels of the rendered window (0, 0 the top left).
struct Region {
    std::string_view name;
    int left = 0;
    int top = 0;
    int right = 0;
    int bottom = 0;
};

/// What rt drew: the linear intensities of the .gro (in display levels: 1 is 255, before -m and
/// clipping) and the 8-bit picture a user sees (after -m and -c).
struct Picture {
    int width = 0;
    int height = 0;
    std::vector<Rgb> levels;  ///< row-major from the top row
    Image8 display;
    std::string output;  ///< what rt printed, standard output then standard error
};

/// Renders `scene` (a path) with `switches` in `folder` and reads both outputs back (the .gro rt
/// writes by default, and a PPM); nothing when rt refuses the switches or fails (the message is
/// put in `error`).
std::optional<Picture> render_picture(const std::filesystem::path& scene,
                                      const std::vector<std::string>& switches,
                                      const std::filesystem::path& folder, std::string& error);

/// How one region of a picture differs from the same region of a base picture.
struct RegionChange {
    Rgb mean_difference;            ///< per channel, in levels (picture minus base)
    double changed_fraction = 0.0;  ///< pixels with some channel off by more than half a level
    double touched_fraction = 0.0;  ///< pixels with some channel off by more than 1e-3 levels
    double display_ratio = 1.0;     ///< mean display value over the base's (8-bit pictures)
    double display_changed = 0.0;   ///< pixels whose 8-bit value differs by more than 1
    double mean() const { return (mean_difference.r + mean_difference.g + mean_difference.b) / 3; }
};

/// Throws std::out_of_range when the region is not inside both pictures.
RegionChange measure_change(const Picture& base, const Picture& picture, const Region& region);

}  // namespace rt::test
