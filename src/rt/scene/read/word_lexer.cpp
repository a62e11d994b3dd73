#include "rt/scene/read/word_lexer.h"

namespace rt {

WordLexer::WordLexer(const SourceText& source, WordLexerOptions options)
    : text_(source.bytes), options_(options) {}

void WordLexer::skip_blanks_and_comments() {
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (c == '\n') {
            ++line_;
            line_start_ = ++pos_;
        } else if (is_blank(c)) {
            ++pos_;
        } else if (c == '#' && options_.hash_comments) {
            while (pos_ < text_.size() && text_[pos_] != '\n') {
                ++pos_;
            }
        } else {
            return;
        }
    }
}

std::optional<Token> WordLexer::scan() {
    skip_blanks_and_comments();
    if (pos_ >= text_.size()) {
        return std::nullopt;
    }
    const std::size_t start = pos_;
    const auto is_brace = [this](char c) { return options_.braces && (c == '{' || c == '}'); };
    if (is_brace(text_[pos_])) {
        ++pos_;
    } else {
        while (pos_ < text_.size() && text_[pos_] != '\n' && !is_blank(text_[pos_]) &&
               !is_brace(text_[pos_]) && !(options_.hash_comments && text_[pos_] == '#')) {
            ++pos_;
        }
    }
    return Token{text_.substr(start, pos_ - start), line_,
                 static_cast<int>(start - line_start_) + 1};
}

std::optional<Token> WordLexer::peek() {
    if (!peeked_) {
        peeked_ = scan();
    }
    return peeked_;
}

std::optional<Token> WordLexer::next() {
    std::optional<Token> word = peeked_ ? peeked_ : scan();
    peeked_.reset();
    if (word) {
        last_line_ = word->line;
    }
    return word;
}

std::int64_t WordLexer::max_words_left() const {
    // Every word but the last needs at least one character and one separator, except braces,
    // which need no separator.
    const std::size_t left = text_.size() - pos_ + 1;
    const std::size_t words = options_.braces ? left : left / 2;
    return static_cast<std::int64_t>(words) + (peeked_ ? 1 : 0);
}

}  // namespace rt
