#include "rt/scene/read/counted_lines.h"

#include "rt/core/error.h"
#include "rt/scene/read/field_reader.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

void LinesLeftOver::warn(const SourceText& source, std::string_view what, std::string_view why,
                         Diagnostics& diagnostics) const {
    if (count_ > 0) {
        diagnostics.warn(fmt::format("{}: {} line{} after the {} ignored{}",
                                     source.at(first_).to_string(), count_, count_ == 1 ? "" : "s",
                                     what, why));
    }
}

CountedLines::CountedLines(const SourceText& source, std::string_view item, std::string_view items)
    : source_(source), items_(items), reader_(source) {
    const std::string what = fmt::format("the {} count", item);
    if (!reader_.next(line_)) {
        throw expected_found(source.at(source.last_line()), what, "end of file");
    }
    count_ = count_from(source, line_.tokens.front(), what, kMaxItemsPerFile);
}

const DollarLine& CountedLines::next_item() {
    if (!reader_.next(line_)) {
        throw InputError(source_.at(source_.last_line()),
                         fmt::format("expected {} {}, found {}", count_, items_, read_));
    }
    ++read_;
    return line_;
}

void CountedLines::skip_the_rest(Diagnostics& diagnostics) {
    LinesLeftOver left;
    while (reader_.next(line_)) {
        left.add(line_.line);
    }
    left.warn(source_, fmt::format("{} {}", count_, items_),
              " (is the count on the first $ line right?)", diagnostics);
}

}  // namespace rt
