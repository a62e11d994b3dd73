// Three nested glass cubes over a floor (tests/data/scene/nested-glass): every glass surface
// reflects and transmits, so the ray tree doubles at each level of maxdepth. The bottom rows see
// only the matte floor and finish at once; the rows through the glass take 2^maxdepth rays.
#pragma once

#include <cstdint>
#include <string>

#include "support/temp_dir.h"

namespace rt::test {

/// Writes the scene as `name`.scn into dir, with its files, at the given maxdepth; `window` is
/// its output matrix (left top right bottom) in the 32 x 24 view.
void write_nested_glass(const TempDir& dir, const std::string& name, int maxdepth,
                        const std::string& window = "0 0 31 23");

/// The rays traced in all, from the "all" row of the -p table on standard output.
std::uint64_t rays_traced(const std::string& profile);

}  // namespace rt::test
