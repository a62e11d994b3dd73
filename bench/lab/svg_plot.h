// Log-log plots of single-thread rays/s, or time per ray, against triangle count, one line per
// intersection method, one panel per mesh and kind of ray; plain SVG, written by hand.
#pragma once

#include <string>
#include <vector>

#include "lab_measure.h"

namespace rt::lab {

/// Throws IoError.
void write_svg_plot(const std::string& file, const std::vector<Measurement>& results);

/// Nanoseconds per ray, one thread, instead of rays/s: how the cost of a ray grows with the
/// mesh. Throws IoError.
void write_time_plot(const std::string& file, const std::vector<Measurement>& results);

}  // namespace rt::lab
