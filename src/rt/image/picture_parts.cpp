#include "rt/image/picture_parts.h"

#include <cstdint>

#include "rt/core/error.h"
#include "rt/core/text.h"

#include <fmt/format.h>

namespace rt {

namespace {

// The part's index and count, when both are whole numbers with 1 <= index <= count.
std::optional<PicturePart> make_part(std::string_view index, std::string_view count) {
    const std::optional<std::int64_t> i = parse_integer(index);
    const std::optional<std::int64_t> n = parse_integer(count);
    if (!i || !n || *n < 1 || *n > 1000000 || *i < 1 || *i > *n) {
        return std::nullopt;
    }
    return PicturePart{static_cast<int>(*i), static_cast<int>(*n)};
}

}  // namespace

PicturePart parse_picture_part(const std::string& text) {
    const std::size_t slash = text.find('/');
    const std::optional<PicturePart> part =
        slash == std::string::npos ? std::nullopt
                                   : make_part(std::string_view(text).substr(0, slash),
                                               std::string_view(text).substr(slash + 1));
    if (!part) {
        throw UsageError(fmt::format(
            "--tile: expected I/N, part I of N parts with 1 <= I <= N (like 2/3), found {}",
            quote_token(text)));
    }
    return *part;
}

PixelRect part_window(const PixelRect& window, PicturePart part) {
    const std::int64_t rows = window.height();
    if (part.count > rows) {
        throw SettingError("picture part", fmt::format("cannot cut a window of {} rows into {} "
                                                       "parts: give at most {} parts",
                                                       rows, part.count, rows));
    }
    const auto first = static_cast<int>((part.index - 1) * rows / part.count);
    const auto end = static_cast<int>(part.index * rows / part.count);
    return {window.left, window.top + first, window.right, window.top + end - 1};
}

std::string format_part_line(PicturePart part) {
    return fmt::format("{} {}", part.index, part.count);
}

std::optional<PicturePart> parse_part_line(std::string_view text) {
    const std::size_t space = text.find(' ');
    if (space == std::string_view::npos) {
        return std::nullopt;
    }
    return make_part(text.substr(0, space), text.substr(space + 1));
}

}  // namespace rt
