// Locale-independent number parsing for every reader and the switch parser.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

/// A finite decimal number taking the whole of text ("2", "-1.5", ".5", "+3e2"); NaN, infinities
/// and trailing characters give nullopt.
std::optional<double> parse_double(std::string_view text);

/// A whole number taking the whole of text ("12", "-3", "+4"). "4.0" is accepted as 4 because old
/// files wrote integer fields with a decimal point; "4.5" is not.
std::optional<std::int64_t> parse_integer(std::string_view text);

/// Quotes a token for an error message, shortening very long ones: 'abc'.
std::string quote_token(std::string_view token);

}  // namespace rt
