#include "rt/core/text.h"

#include <charconv>
#include <cmath>

namespace rt {

std::optional<double> parse_double(std::string_view text) {
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
            return std::nullopt;
        }
    }
    if (text.empty()) {
        return std::nullopt;
    }
    double value = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
    std::string_view digits = text;
    if (!digits.empty() && digits.front() == '+') {
        digits.remove_prefix(1);
    }
    std::int64_t value = 0;
    const char* end = digits.data() + digits.size();
    auto [ptr, ec] = std::from_chars(digits.data(), end, value);
    if (ec == std::errc() && ptr == end && !digits.empty()) {
        return value;
    }
    // Integer fields written as "4.0" are common in hand-made files.
    std::optional<double> real = parse_double(text);
    if (real && *real == std::floor(*real) && std::fabs(*real) < 9.0e15) {
        return static_cast<std::int64_t>(*real);
    }
    return std::nullopt;
}

std::string quote_token(std::string_view token) {
    constexpr std::size_t kMaxShown = 40;
    std::string quoted(1, '\'');
    quoted.append(token.substr(0, kMaxShown));
    if (token.size() > kMaxShown) {
        quoted.append("...");
    }
    quoted.push_back('\'');
    return quoted;
}

std::string cat(std::initializer_list<std::string_view> pieces) {
    std::string text;
    for (const std::string_view piece : pieces) {
        text += piece;
    }
    return text;
}

}  // namespace rt
