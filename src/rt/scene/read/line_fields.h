// One $ line read field by field (Attributes and shape files, manual 2.3-2.4): a line with too
// few numbers names the missing field; words after the last field are a description.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "rt/scene/read/dollar_lines.h"
#include "rt/scene/read/field_reader.h"

namespace rt {

class LineFields {
public:
    /// Both must outlive the reader.
    LineFields(const SourceText& source, const DollarLine& line) : source_(source), line_(line) {}

    double number(std::string_view what) { return number_from(source_, take(what), what); }
    /// A number from -limit to limit, or "expected <what> (-L to L), found 'tok'".
    double number_within(std::string_view what, double limit);
    std::int64_t integer(std::string_view what) { return integer_from(source_, take(what), what); }
    SourceLocation location() const { return source_.at(line_.line); }
    /// How many numbers follow, one after another, from the next field on.
    std::size_t numbers_ahead() const;

private:
    Token take(std::string_view what);

    const SourceText& source_;
    const DollarLine& line_;
    std::size_t next_ = 0;
};

}  // namespace rt
