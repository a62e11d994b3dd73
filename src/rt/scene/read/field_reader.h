// Typed reading of tokens with "expected X, found Y" errors, shared by every reader: numbers go
// through rt::parse_double / rt::parse_integer only, and counts are checked against limits.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "rt/core/error.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/read/token.h"

namespace rt {

/// The location of a token in a source.
inline SourceLocation location_of(const SourceText& source, const Token& token) {
    return source.at(token.line, token.column);
}

/// A finite number, or "expected <what>, found 'tok'".
double number_from(const SourceText& source, const Token& token, std::string_view what);
/// A number from -limit to limit, or "expected <what> (-L to L), found 'tok'".
double number_within(const SourceText& source, const Token& token, std::string_view what,
                     double limit);
/// number_within kMaxCoordinate (reader_limits.h).
double coordinate_from(const SourceText& source, const Token& token, std::string_view what);
/// A whole number, or "expected <what> (a whole number), found 'tok'".
std::int64_t integer_from(const SourceText& source, const Token& token, std::string_view what);
/// A whole number in lo..hi, or "expected <what> (lo to hi), found 'tok'".
std::int64_t integer_in(const SourceText& source, const Token& token, std::string_view what,
                        std::int64_t lo, std::int64_t hi);
/// A count 0..limit: negative is "expected <what> (0 or more), found '-1'"; too large is
/// "<What> is N, more than the limit of L".
std::int64_t count_from(const SourceText& source, const Token& token, std::string_view what,
                        std::int64_t limit);

/// "1 shape", "2 shapes".
std::string count_of(std::int64_t n, std::string_view noun);
/// "1", "-0.5", "2.5e+20": numbers in messages and traces, shortest round-trip form.
std::string show_number(double value);
/// "(1, -0.5, 2)".
std::string show_point(double x, double y, double z);

}  // namespace rt
