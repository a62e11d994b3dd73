// The .scn read as a stream of items over its $ lines (manual 2.2; rules in docs/formats.md):
// an item takes its tokens in order, across line ends if it must; after an item, words left on
// its last line are a comment ("$ 1 optical surface") unless they begin with a number or '@'.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "rt/core/vec3.h"
#include "rt/scene/read/dollar_lines.h"
#include "rt/scene/read/field_reader.h"

namespace rt {

class ItemStream {
public:
    /// The source must outlive the stream.
    explicit ItemStream(const SourceText& source);

    const SourceText& source() const { return source_; }
    /// The next token, or nullptr at the end of the file.
    const Token* peek();
    /// Takes the next token; at the end of the file, "expected <what>, found end of file".
    Token take(std::string_view what);
    double number(std::string_view what) { return number_from(source_, take(what), what); }
    /// A number within the coordinate range (reader_limits.h).
    double coordinate(std::string_view what) { return coordinate_from(source_, take(what), what); }
    /// Three numbers, named "<what> x", "<what> y" and "<what> z" in messages.
    Vec3 triple(const std::string& what) {
        return {number(what + " x"), number(what + " y"), number(what + " z")};
    }
    /// Three numbers within the coordinate range, named as triple() names them.
    Vec3 coordinates(const std::string& what) {
        return {coordinate(what + " x"), coordinate(what + " y"), coordinate(what + " z")};
    }
    std::int64_t integer(std::string_view what) { return integer_from(source_, take(what), what); }
    std::int64_t count(std::string_view what, std::int64_t limit) {
        return count_from(source_, take(what), what, limit);
    }

    /// Ends an item: skips a comment left on the line of the last token taken.
    void end_item();
    /// Whether the next token is on the line of the last token taken.
    bool next_on_same_line();
    /// Skips whatever is left on the line of the last token taken.
    void skip_rest_of_line();
    /// Takes the rest of the current line if something is left on it, else the next whole $ line;
    /// false at the end of the file.
    bool take_line(DollarLine& out);
    /// The line of the last token taken.
    int line() const { return last_line_; }
    /// Where "end of file" is.
    SourceLocation end_location() const { return source_.at(source_.last_line()); }

private:
    bool fill();

    const SourceText& source_;
    DollarLineReader reader_;
    DollarLine current_;
    std::size_t next_ = 0;  ///< next token of current_
    int last_line_ = 0;
};

}  // namespace rt
