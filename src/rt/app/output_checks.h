// The checks an output path passes before the render starts, so that a typo, a read-only or full
// folder never costs a finished render (docs/formats.md, "Outputs").
#pragma once

#include <cstdint>
#include <filesystem>

#include "rt/core/bounds.h"

namespace rt {

/// Throws IoError unless a file can be created in path's folder (tried for real, with the
/// temporary name the writer uses, and removed) and path is not a device, a pipe or a socket,
/// which the writer would replace.
void check_output_folder(const std::filesystem::path& path);

/// The bytes an output of this window takes at most: .gro, .exr and .ppm uncompressed; .png as
/// its raw 8-bit pixels (compression usually makes it smaller).
std::uint64_t output_size_bound(const std::filesystem::path& path, const PixelRect& window);

/// Throws IoError when `needed` bytes exceed `free_bytes`, the space left in path's folder.
void check_free_space(const std::filesystem::path& path, std::uint64_t needed,
                      std::uint64_t free_bytes);

/// check_free_space with the space statvfs reports for path's folder (for root, the blocks
/// reserved for it too); nothing when it cannot be read.
void check_output_space(const std::filesystem::path& path, const PixelRect& window);

}  // namespace rt
