// Joining the part files of `rt --tile I/N` into the whole picture (docs/distributed.md).
#pragma once

#include <filesystem>
#include <vector>

#include "rt/image/film.h"

namespace rt {

/// Reads the part files and joins them into the film a single render would have made: the
/// same window and pixels, the header of part 1 without its part lines. Refuses (rt::InputError
/// naming the file) a file that is not a finished part, parts whose headers disagree on anything
/// but their window, rows finished, creation time and part number (different scenes, switches,
/// seeds or programs), the same part twice, and a window that is not the part's band; and
/// (rt::UsageError) missing parts, by number. Throws as read_gro does for unreadable files.
Film merge_parts(const std::vector<std::filesystem::path>& paths);

}  // namespace rt
