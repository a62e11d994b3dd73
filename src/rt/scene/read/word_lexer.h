// A free-form stream of words over a whole file, where line breaks carry no meaning (optical
// surface filetype 0, manual 2.5, and the Phigs+ subset of filetype 1). With braces on, '{' and
// '}' are words of their own even when attached ("{solid"), for filetype 2.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "rt/scene/read/source_text.h"
#include "rt/scene/read/token.h"

namespace rt {

struct WordLexerOptions {
    bool braces = false;         ///< '{' and '}' are separate words
    bool hash_comments = false;  ///< '#' starts a comment running to the end of the line
};

class WordLexer {
public:
    /// The source must outlive the lexer and every token it yields.
    explicit WordLexer(const SourceText& source, WordLexerOptions options = {});

    /// The next word without taking it; nullopt at the end of the file.
    std::optional<Token> peek();
    std::optional<Token> next();
    /// An upper bound on the words left, to check a count before reserving memory.
    std::int64_t max_words_left() const;
    /// The line of the last word taken (1 before any).
    int line() const { return last_line_; }

private:
    void skip_blanks_and_comments();
    std::optional<Token> scan();

    std::string_view text_;
    WordLexerOptions options_;
    std::size_t pos_ = 0;
    int line_ = 1;
    std::size_t line_start_ = 0;
    int last_line_ = 1;
    std::optional<Token> peeked_;
};

}  // namespace rt
