// A picture cut into N horizontal bands (`rt --tile I/N`), each rendered into its own part file,
// and joined again by `merge` (docs/distributed.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "rt/core/bounds.h"

namespace rt {

/// The I-th of N parts (1-based): the rows of a window split into N bands from the top, as even
/// as whole rows allow.
struct PicturePart {
    int index = 1;
    int count = 1;
    friend constexpr bool operator==(const PicturePart&, const PicturePart&) = default;
};

/// Reads "I/N" (1 <= I <= N). Throws rt::UsageError saying what was expected.
PicturePart parse_picture_part(const std::string& text);

/// The band of window that part covers: full width, rows top + floor((I-1)H/N) to
/// top + floor(IH/N) - 1. Throws rt::SettingError when the window has fewer rows than parts.
PixelRect part_window(const PixelRect& window, PicturePart part);

/// "2 3": the value of the part file's `part` header line.
std::string format_part_line(PicturePart part);

/// Reads a `part` header value ("2 3"); nothing if it is not two whole numbers 1 <= I <= N.
std::optional<PicturePart> parse_part_line(std::string_view text);

}  // namespace rt
