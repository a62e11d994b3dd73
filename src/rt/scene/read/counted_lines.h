// The files of $ lines that start with a count (Attributes and shape files, manual 2.3-2.4): the
// first $ line holds the number of item lines after it, one item per line.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/dollar_lines.h"

namespace rt {

/// Lines left after the last item a file or section should hold: readers skip them with one
/// warning that names the first and says how many.
class LinesLeftOver {
public:
    void add(int line) { first_ = count_++ == 0 ? line : first_; }
    /// "FILE:LINE: N lines after the WHAT ignored" followed by `why`; nothing if none were left.
    void warn(const SourceText& source, std::string_view what, std::string_view why,
              Diagnostics& diagnostics) const;

private:
    int count_ = 0;
    int first_ = 0;  ///< the line number of the first
};

class CountedLines {
public:
    /// Reads the count from the first $ line. `item` names one item in messages ("attribute"),
    /// `items` several ("attributes"). The source must outlive the reader.
    CountedLines(const SourceText& source, std::string_view item, std::string_view items);

    std::int64_t count() const { return count_; }
    /// The next item's line; throws rt::InputError when the file ends before `count()` items.
    const DollarLine& next_item();
    /// Skips the lines after the last item, with one warning if there are any.
    void skip_the_rest(Diagnostics& diagnostics);

private:
    const SourceText& source_;
    std::string items_;
    DollarLineReader reader_;
    DollarLine line_;
    std::int64_t count_ = 0;
    std::int64_t read_ = 0;
};

}  // namespace rt
