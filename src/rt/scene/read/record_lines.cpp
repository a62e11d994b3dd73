#include "rt/scene/read/record_lines.h"

#include <algorithm>
#include <string>

#include "rt/core/text.h"
#include "rt/scene/read/field_reader.h"

namespace rt {

bool RecordReader::next(DollarLine& out) {
    while (pos_ < text_.size()) {
        std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) {
            end = text_.size();  // no final newline
        }
        std::string_view line = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        ++line_;
        line = line.substr(0, std::min(line.size(), line.find('#')));
        out.line = line_;
        out.end_column = static_cast<int>(line.size()) + 1;
        out.tokens.clear();
        append_words(line, 0, line_, out);
        if (!out.tokens.empty()) {
            return true;
        }
    }
    return false;
}

std::int64_t RecordReader::max_records_left() const {
    if (pos_ >= text_.size()) {
        return 0;
    }
    return static_cast<std::int64_t>(
               std::count(text_.begin() + static_cast<std::ptrdiff_t>(pos_), text_.end(), '\n')) +
           1;
}

void expect_record_end(const SourceText& source, const DollarLine& record, std::size_t used,
                       std::string_view what) {
    if (record.tokens.size() > used) {
        const Token& extra = record.tokens[used];
        throw expected_found(location_of(source, extra),
                             "the end of the line after " + std::string(what),
                             quote_token(extra.text));
    }
}

}  // namespace rt
