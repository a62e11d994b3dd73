// The line records of the -V grid and texture map files (docs/formats.md): '#' starts a comment
// that runs to the end of the line, blank lines are skipped, and every other line is one record,
// read field by field with rt::LineFields.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "rt/scene/read/dollar_lines.h"
#include "rt/scene/read/source_text.h"

namespace rt {

class RecordReader {
public:
    /// The source must outlive the reader and every token it yields.
    explicit RecordReader(const SourceText& source) : source_(source), text_(source.bytes) {}

    /// The next record (its words in `tokens`); false at the end of the file.
    bool next(DollarLine& out);
    /// An upper bound on the records left, to check a count before reserving memory.
    std::int64_t max_records_left() const;
    /// Where "found end of file" is.
    SourceLocation end_location() const { return source_.at(source_.last_line()); }

private:
    const SourceText& source_;
    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 0;
};

/// Throws "expected the end of the line after <what>, found 'word'" when `record` has more than
/// `used` words.
void expect_record_end(const SourceText& source, const DollarLine& record, std::size_t used,
                       std::string_view what);

}  // namespace rt
