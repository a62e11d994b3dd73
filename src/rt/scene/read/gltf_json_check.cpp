#include "rt/scene/read/gltf_json_check.h"

#include <algorithm>
#include <cstring>
#include <string_view>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"

#include <fmt/format.h>

namespace rt {

namespace {

// Deeper than any glTF writer nests, and far from the depth that overflows Assimp's parser.
constexpr std::size_t kMaxJsonDepth = 1000;
constexpr int kEnd = -1;

// The bytes of the JSON, read in blocks (at most `limit` of them: a .glb's JSON chunk), with the
// line of each.
class JsonBytes {
public:
    JsonBytes(std::istream& in, std::uintmax_t limit) : in_(in), left_(limit) {}

    int peek() {
        if (at_ == size_ && !fill()) {
            return kEnd;
        }
        return static_cast<unsigned char>(buffer_[at_]);
    }
    int get() {
        const int c = peek();
        if (c != kEnd) {
            ++at_;
            line_ += after_line_break_ ? 1 : 0;
            after_line_break_ = c == '\n';
        }
        return c;
    }
    /// The line of the next byte; at the end, of the last one.
    int line() { return line_ + (after_line_break_ && peek() != kEnd ? 1 : 0); }
    /// Takes the bytes of a string up to its next quote, backslash or control byte at once (a
    /// buffer written into the JSON in base64 is megabytes of them).
    void skip_plain_string_bytes() {
        while (peek() != kEnd) {
            const std::size_t start = at_;
            while (at_ < size_) {
                const auto c = static_cast<unsigned char>(buffer_[at_]);
                if (c == '"' || c == '\\' || c < 0x20) {
                    break;
                }
                ++at_;
            }
            if (at_ > start) {
                after_line_break_ = false;
            }
            if (at_ < size_) {
                return;
            }
        }
    }

private:
    bool fill() {
        const auto want = static_cast<std::streamsize>(
            std::min<std::uintmax_t>(left_, static_cast<std::uintmax_t>(buffer_.size())));
        in_.read(buffer_.data(), want);
        size_ = static_cast<std::size_t>(in_.gcount());
        left_ -= size_;
        at_ = 0;
        return size_ > 0;
    }

    std::istream& in_;
    std::uintmax_t left_;
    std::vector<char> buffer_ = std::vector<char>(std::size_t{1} << 16);
    std::size_t at_ = 0;
    std::size_t size_ = 0;
    int line_ = 1;
    bool after_line_break_ = false;
};

bool is_digit(int c) {
    return c >= '0' && c <= '9';
}

bool is_hex_digit(int c) {
    return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

// The walk, one value after another. Containers are kept on a stack of its own, so deep nesting
// costs no call stack here.
class JsonWalk {
public:
    /// `chunk`: the JSON is a .glb's chunk, whose lines messages name apart from the file.
    JsonWalk(JsonBytes& bytes, const std::string& name, bool chunk)
        : bytes_(bytes), name_(name), chunk_(chunk) {}

    void document() {
        blanks();
        if (bytes_.peek() == 0xef) {
            bytes_.get();
            if (bytes_.get() == 0xbb && bytes_.peek() == 0xbf) {
                fail("'{' to start the glTF object",
                     "a UTF-8 byte order mark (Assimp's parser reads JSON without one)");
            }
            fail("'{' to start the glTF object", "byte 0xef");
        }
        if (bytes_.peek() != '{') {
            fail("'{' to start the glTF object");
        }
        value();
        blanks();
        if (bytes_.peek() != kEnd && bytes_.peek() != 0) {
            fail(chunk_ ? "the end of the JSON chunk after the glTF object"
                        : "the end of the file after the glTF object");
        }
    }

private:
    // One value, with all that nests in it.
    void value() {
        for (;;) {
            blanks();
            const int c = bytes_.peek();
            if (c == '{' || c == '[') {
                open(static_cast<char>(c));
                if (c == '{' && bytes_.peek() != '}') {
                    member_name("a member name in quotes or '}'");
                    continue;
                }
                if (c == '[' && bytes_.peek() != ']') {
                    continue;
                }
            } else {
                scalar();
            }
            if (!close_values()) {
                return;
            }
        }
    }

    void open(char c) {
        if (stack_.size() == kMaxJsonDepth) {
            throw InputError(where(), detail(fmt::format("the JSON's arrays and objects nest more "
                                                         "than {} deep",
                                                         kMaxJsonDepth)));
        }
        bytes_.get();
        stack_.push_back(c);
        blanks();
    }

    // After a value: closes the containers it ends, up to a comma before the next value (true),
    // or to the end of the outermost (false).
    bool close_values() {
        while (!stack_.empty()) {
            blanks();
            const bool object = stack_.back() == '{';
            const int c = bytes_.peek();
            if (c == ',') {
                bytes_.get();
                if (object) {
                    member_name("a member name in quotes");
                }
                return true;
            }
            if (c != (object ? '}' : ']')) {
                fail(object ? "',' or '}' in an object" : "',' or ']' in an array");
            }
            bytes_.get();
            stack_.pop_back();
        }
        return false;
    }

    void member_name(std::string_view expected) {
        blanks();
        if (bytes_.peek() != '"') {
            fail(expected);
        }
        string();
        blanks();
        if (bytes_.peek() != ':') {
            fail("':' after the member name");
        }
        bytes_.get();
    }

    void scalar() {
        const int c = bytes_.peek();
        if (c == '"') {
            string();
        } else if (c == '-' || is_digit(c)) {
            number();
        } else {
            literal();
        }
    }

    void string() {
        bytes_.get();
        for (;;) {
            bytes_.skip_plain_string_bytes();
            const int c = bytes_.peek();
            if (c == '"') {
                bytes_.get();
                return;
            }
            if (c != '\\') {
                fail("'\"' to end the string");  // a control byte, or the end
            }
            bytes_.get();
            escape();
        }
    }

    void escape() {
        const int c = bytes_.peek();
        if (c == 'u') {
            bytes_.get();
            for (int i = 0; i < 4; ++i) {
                if (!is_hex_digit(bytes_.peek())) {
                    fail("4 hex digits after '\\u'");
                }
                bytes_.get();
            }
        } else if (c != kEnd && std::strchr("\"\\/bfnrt", c) != nullptr) {
            bytes_.get();
        } else {
            fail("one of \" \\ / b f n r t u after '\\'");
        }
    }

    void number() {
        if (bytes_.peek() == '-') {
            bytes_.get();
        }
        if (!is_digit(bytes_.peek())) {
            fail("a digit in the number");
        }
        if (bytes_.get() != '0') {  // no other number starts with 0
            digits();
        }
        if (bytes_.peek() == '.') {
            bytes_.get();
            if (!is_digit(bytes_.peek())) {
                fail("a digit after the decimal point");
            }
            digits();
        }
        if (bytes_.peek() == 'e' || bytes_.peek() == 'E') {
            bytes_.get();
            if (bytes_.peek() == '+' || bytes_.peek() == '-') {
                bytes_.get();
            }
            if (!is_digit(bytes_.peek())) {
                fail("a digit in the exponent");
            }
            digits();
        }
    }

    void digits() {
        while (is_digit(bytes_.peek())) {
            bytes_.get();
        }
    }

    // true, false or null; any other word is named whole.
    void literal() {
        std::string word;
        while (word.size() < 40 && ((bytes_.peek() >= 'a' && bytes_.peek() <= 'z') ||
                                    (bytes_.peek() >= 'A' && bytes_.peek() <= 'Z'))) {
            word.push_back(static_cast<char>(bytes_.get()));
        }
        if (word != "true" && word != "false" && word != "null") {
            fail("a value", word.empty() ? found() : quote_token(word));
        }
    }

    void blanks() {
        for (int c = bytes_.peek(); c == ' ' || c == '\t' || c == '\n' || c == '\r';
             c = bytes_.peek()) {
            bytes_.get();
        }
    }

    std::string found() {
        const int c = bytes_.peek();
        if (c == kEnd) {
            return chunk_ ? "the end of the JSON chunk" : "end of file";
        }
        if (c == '\n') {
            return "a line break";
        }
        if (c >= 0x20 && c < 0x7f) {
            return fmt::format("'{}'", static_cast<char>(c));
        }
        return fmt::format("byte 0x{:02x}", c);
    }

    SourceLocation where() { return {name_, chunk_ ? 0 : bytes_.line(), 0}; }
    std::string detail(const std::string& message) {
        return chunk_ ? fmt::format("line {} of the JSON chunk: {}", bytes_.line(), message)
                      : message;
    }

    [[noreturn]] void fail(std::string_view expected) { fail(expected, found()); }
    [[noreturn]] void fail(std::string_view expected, const std::string& found) {
        throw InputError(where(), detail(fmt::format("expected {}, found {}", expected, found)));
    }

    JsonBytes& bytes_;
    const std::string& name_;
    bool chunk_;
    std::vector<char> stack_;
};

}  // namespace

void check_gltf_json(std::istream& in, std::uintmax_t bytes, const std::string& name, bool chunk) {
    JsonBytes json(in, bytes);
    JsonWalk(json, name, chunk).document();
}

}  // namespace rt
