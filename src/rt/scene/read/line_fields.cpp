#include "rt/scene/read/line_fields.h"

namespace rt {

Token LineFields::take(std::string_view what) {
    if (next_ >= line_.tokens.size()) {
        throw expected_found(source_.at(line_.line, line_.end_column), std::string(what),
                             "end of line");
    }
    return line_.tokens[next_++];
}

double LineFields::number_within(std::string_view what, double limit) {
    return rt::number_within(source_, take(what), what, limit);
}

}  // namespace rt
