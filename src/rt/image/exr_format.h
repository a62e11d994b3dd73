// OpenEXR pictures: the film's linear intensities in a file any compositing or HDR tool reads.
// The view area is the EXR display window and the film's window its data window; the display
// mapping and the provenance travel as attributes, so .gro -> .exr -> .gro loses nothing
// (docs/formats.md, "OpenEXR").
#pragma once

#include <filesystem>

#include "rt/image/film.h"

namespace rt {

/// Writes film to path, atomically, as a scan-line OpenEXR file of 32-bit float R, G and B
/// (ZIP-compressed, lossless). Throws rt::Error if the film cannot be stored (check_storable)
/// and rt::IoError on I/O failure.
void write_exr(const Film& film, const std::filesystem::path& path);

/// Reads an OpenEXR file with R, G and B channels (half, float or unsigned int; converted to
/// float) whose display window starts at (0, 0) and holds the data window. Attributes rt did not
/// write are ignored; those it did restore the display mapping, the rows finished and the
/// provenance. Throws rt::InputError for a file rt cannot take (with the reason) and
/// rt::IoError when it cannot be read.
Film read_exr(const std::filesystem::path& path);

}  // namespace rt
