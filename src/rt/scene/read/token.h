// A word of an input file with the place it came from.
#pragma once

#include <string_view>

namespace rt {

struct Token {
    std::string_view text;  ///< points into the SourceText's bytes
    int line = 0;           ///< 1-based
    int column = 0;         ///< 1-based, in bytes
};

/// Spaces, tabs, carriage returns (of CRLF line ends), form and vertical feeds.
constexpr bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace rt
