// The text header of a .gro file: reading it line by line with strict checks, and writing it.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "rt/image/film.h"

namespace rt {

/// Everything a .gro header says, plus where the header ends.
struct GroHeader {
    int view_width = 0;
    int view_height = 0;
    PixelRect window;
    int first_finished_row = 0;
    DisplayMapping mapping;
    FilmProvenance provenance;
    FilmPart part;
    /// Every 'key value' line as read, in order, unknown keys included (merge compares them).
    std::vector<std::pair<std::string, std::string>> fields;
    int lines = 0;            ///< header lines, the magic line and 'end' included
    std::uint64_t bytes = 0;  ///< header bytes, the newline after 'end' included
};

/// Reads and validates the header from in (positioned at the start of the file). file names the
/// file in error messages. Throws rt::InputError.
GroHeader read_gro_header(std::istream& in, const std::string& file);

/// The header text for film, 'end' line included. Text fields have control characters replaced
/// by spaces, since a header line ends at a newline.
std::string format_gro_header(const Film& film);

}  // namespace rt
