// Helpers of the model file tests: a .gro's pixels, and the shipped bunny rewritten as OBJ.
#pragma once

#include <filesystem>
#include <string>

namespace rt::test {

/// The pixel block of a .gro file: what follows the header's "end" line.
std::string gro_pixels(const std::filesystem::path& gro);

/// The shipped scenes/models/bunny.ply (ASCII, triangles) rewritten as OBJ: the same numbers,
/// 1-based indices.
std::string bunny_as_obj();

}  // namespace rt::test
