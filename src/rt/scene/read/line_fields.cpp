#include "rt/scene/read/line_fields.h"

#include "rt/core/text.h"

namespace rt {

Token LineFields::take(std::string_view what) {
    if (next_ >= line_.tokens.size()) {
        throw expected_found(source_.at(line_.line, line_.end_column), std::string(what),
                             "end of line");
    }
    return line_.tokens[next_++];
}

std::size_t LineFields::numbers_ahead() const {
    std::size_t count = 0;
    while (next_ + count < line_.tokens.size() &&
           parse_double(line_.tokens[next_ + count].text).has_value()) {
        ++count;
    }
    return count;
}

double LineFields::number_within(std::string_view what, double limit) {
    return rt::number_within(source_, take(what), what, limit);
}

}  // namespace rt
