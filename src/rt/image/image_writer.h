// Writing a film in the format its file name asks for: .gro, .png or .ppm.
#pragma once

#include <filesystem>

#include "rt/image/film.h"

namespace rt {

enum class ImageFormat { Gro, Png, Ppm };

/// The format named by path's extension, case-insensitively. Throws rt::UsageError
/// ("cannot write 'x.jpg': unknown image format '.jpg' (known: .gro, .png, .ppm)") otherwise, so
/// a command line can be checked before any rendering.
ImageFormat image_format_for(const std::filesystem::path& path);

/// Writes film to path, atomically, in the format its extension names: .gro keeps the linear
/// intensities of the whole window; .png and .ppm hold the window's 8-bit picture under
/// film.mapping (unfinished rows black).
void write_image(const Film& film, const std::filesystem::path& path);

}  // namespace rt
