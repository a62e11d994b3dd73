// The "$ line" convention of .scn, Attributes and shape files (manual 2.2-2.4): only lines whose
// first non-blank character is '$' count; the text after the '$' is split into tokens at blanks.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "rt/scene/read/source_text.h"
#include "rt/scene/read/token.h"

namespace rt {

struct DollarLine {
    int line = 0;
    int end_column = 0;  ///< just past the last character, for "found end of line"
    std::vector<Token> tokens;
};

/// Appends the words of `line` from column `from` on (split at blanks) to `out.tokens`, each with
/// its line and 1-based column.
void append_words(std::string_view line, std::size_t from, int line_number, DollarLine& out);

class DollarLineReader {
public:
    /// The source must outlive the reader and every token it yields.
    explicit DollarLineReader(const SourceText& source) : text_(source.bytes) {}

    /// The next $ line holding at least one token (a bare '$' is skipped); false at the end.
    bool next(DollarLine& out);

private:
    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 0;
};

}  // namespace rt
