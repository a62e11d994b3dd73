// Writing a film in the format its file name asks for: .gro, .exr, .png or .ppm.
#pragma once

#include <filesystem>

#include "rt/image/film.h"

namespace rt {

enum class ImageFormat { Gro, Exr, Png, Ppm };

/// The format named by path's extension, case-insensitively. Throws rt::UsageError
/// ("cannot write 'x.jpg': unknown image format '.jpg' (known: .gro, .exr, .png, .ppm)")
/// otherwise, so
/// a command line can be checked before any rendering.
ImageFormat image_format_for(const std::filesystem::path& path);

/// Writes film to path, atomically, in the format its extension names: .gro and .exr keep the
/// linear intensities of the whole window (as 32-bit floats); .png and .ppm hold the window's
/// 8-bit picture under film.mapping (unfinished rows black).
void write_image(const Film& film, const std::filesystem::path& path);

/// Reads a picture that keeps the linear intensities, .gro or .exr by the extension (any other
/// name is read as .gro). Throws as read_gro and read_exr do.
Film read_linear_image(const std::filesystem::path& path);

}  // namespace rt
