#include "rt/scene/read/field_reader.h"

#include <cmath>

#include "rt/core/text.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

double number_from(const SourceText& source, const Token& token, std::string_view what) {
    if (const auto value = parse_double(token.text)) {
        return *value;
    }
    throw expected_found(location_of(source, token), std::string(what), quote_token(token.text));
}

double number_within(const SourceText& source, const Token& token, std::string_view what,
                     double limit) {
    const auto value = parse_double(token.text);
    if (value && std::fabs(*value) <= limit) {
        return *value;
    }
    throw expected_found(location_of(source, token),
                         fmt::format("{} ({:g} to {:g})", what, -limit, limit),
                         quote_token(token.text));
}

double coordinate_from(const SourceText& source, const Token& token, std::string_view what) {
    return number_within(source, token, what, kMaxCoordinate);
}

std::int64_t integer_from(const SourceText& source, const Token& token, std::string_view what) {
    if (const auto value = parse_integer(token.text)) {
        return *value;
    }
    throw expected_found(location_of(source, token), std::string(what) + " (a whole number)",
                         quote_token(token.text));
}

std::int64_t integer_in(const SourceText& source, const Token& token, std::string_view what,
                        std::int64_t lo, std::int64_t hi) {
    const auto value = parse_integer(token.text);
    if (value && *value >= lo && *value <= hi) {
        return *value;
    }
    throw expected_found(location_of(source, token), fmt::format("{} ({} to {})", what, lo, hi),
                         quote_token(token.text));
}

std::int64_t count_from(const SourceText& source, const Token& token, std::string_view what,
                        std::int64_t limit) {
    const std::int64_t count = integer_from(source, token, what);
    if (count < 0) {
        throw expected_found(location_of(source, token), std::string(what) + " (0 or more)",
                             quote_token(token.text));
    }
    if (count > limit) {
        std::string subject(what);
        if (subject.rfind("the ", 0) == 0) {
            subject[0] = 'T';
        }
        throw InputError(location_of(source, token),
                         fmt::format("{} is {}, more than the limit of {}", subject, count, limit));
    }
    return count;
}

std::string count_of(std::int64_t n, std::string_view noun) {
    return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s");
}

std::string show_number(double value) {
    return fmt::format("{}", value);
}

std::string show_point(double x, double y, double z) {
    return fmt::format("({}, {}, {})", x, y, z);
}

}  // namespace rt
