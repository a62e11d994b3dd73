// Text for every reader, the switch parser and the help: locale-independent number parsing,
// tokens quoted for messages, strings joined from pieces.
#pragma once

#include <cstdint>
#include <initializer_list>
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

/// One string from pieces; also keeps GCC 12 from misreading `"text" + std::string`
/// (-Wrestrict).
std::string cat(std::initializer_list<std::string_view> pieces);

}  // namespace rt
