#include "rt/scene/read/dollar_lines.h"

namespace rt {

void append_words(std::string_view line, std::size_t from, int line_number, DollarLine& out) {
    std::size_t i = from;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i])) {
            ++i;
        }
        if (i > start) {
            out.tokens.push_back(
                {line.substr(start, i - start), line_number, static_cast<int>(start) + 1});
        }
    }
}

bool DollarLineReader::next(DollarLine& out) {
    while (pos_ < text_.size()) {
        std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) {
            end = text_.size();  // no final newline
        }
        const std::string_view line = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        ++line_;
        std::size_t first = 0;
        while (first < line.size() && is_blank(line[first])) {
            ++first;
        }
        if (first == line.size() || line[first] != '$') {
            continue;
        }
        out.line = line_;
        out.end_column = static_cast<int>(line.size()) + 1;
        out.tokens.clear();
        append_words(line, first + 1, line_, out);
        if (!out.tokens.empty()) {
            return true;
        }
    }
    return false;
}

}  // namespace rt
