#include "rt/scene/read/item_stream.h"

#include "rt/core/text.h"

namespace rt {

ItemStream::ItemStream(const SourceText& source) : source_(source), reader_(source) {}

bool ItemStream::fill() {
    while (next_ >= current_.tokens.size()) {
        if (!reader_.next(current_)) {
            current_.tokens.clear();
            next_ = 0;
            return false;
        }
        next_ = 0;
    }
    return true;
}

const Token* ItemStream::peek() {
    return fill() ? &current_.tokens[next_] : nullptr;
}

Token ItemStream::take(std::string_view what) {
    if (!fill()) {
        throw expected_found(end_location(), std::string(what), "end of file");
    }
    const Token token = current_.tokens[next_++];
    last_line_ = token.line;
    return token;
}

bool ItemStream::next_on_same_line() {
    return next_ < current_.tokens.size() && current_.tokens[next_].line == last_line_;
}

void ItemStream::end_item() {
    if (!next_on_same_line()) {
        return;
    }
    const std::string_view word = current_.tokens[next_].text;
    if (!parse_double(word) && word.front() != '@') {
        skip_rest_of_line();
    }
}

void ItemStream::skip_rest_of_line() {
    if (next_on_same_line()) {
        next_ = current_.tokens.size();
    }
}

bool ItemStream::take_line(DollarLine& out) {
    if (!fill()) {
        return false;
    }
    out.line = current_.line;
    out.end_column = current_.end_column;
    out.tokens.assign(current_.tokens.begin() + static_cast<std::ptrdiff_t>(next_),
                      current_.tokens.end());
    next_ = current_.tokens.size();
    last_line_ = out.line;
    return true;
}

}  // namespace rt
