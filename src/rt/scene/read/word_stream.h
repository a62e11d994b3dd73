// Typed reading over a WordLexer, with "expected X, found Y" errors at the word's line.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "rt/core/text.h"
#include "rt/core/vec3.h"
#include "rt/scene/read/field_reader.h"
#include "rt/scene/read/word_lexer.h"

namespace rt {

class WordStream {
public:
    /// The source must outlive the stream.
    WordStream(const SourceText& source, WordLexerOptions options = {})
        : source_(source), lexer_(source, options) {}

    const SourceText& source() const { return source_; }
    WordLexer& lexer() { return lexer_; }

    /// The next word; at the end of the file, "expected <what>, found end of file".
    Token take(std::string_view what) {
        if (auto word = lexer_.next()) {
            return *word;
        }
        throw expected_found(source_.at(source_.last_line()), std::string(what), "end of file");
    }
    double number(std::string_view what) { return number_from(source_, take(what), what); }
    std::int64_t integer(std::string_view what) { return integer_from(source_, take(what), what); }
    std::int64_t count(std::string_view what, std::int64_t limit) {
        return count_from(source_, take(what), what, limit);
    }
    /// Takes the next word, which must be exactly `word`.
    Token expect(std::string_view word, std::string_view what) {
        const Token token = take(what);
        if (token.text != word) {
            throw expected_found(location_of(source_, token), std::string(what),
                                 quote_token(token.text));
        }
        return token;
    }
    Vec3 point(const std::string& what) {
        Vec3 p;
        p.x = number("the x of " + what);
        p.y = number("the y of " + what);
        p.z = number("the z of " + what);
        return p;
    }

private:
    const SourceText& source_;
    WordLexer lexer_;
};

}  // namespace rt
