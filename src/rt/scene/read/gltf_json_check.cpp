#include "rt/scene/read/gltf_json_check.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"

#include <fmt/format.h>

#include <rapidjson/reader.h>

namespace rt {

namespace {

// Deeper than any glTF writer nests, and far from the depth that overflows Assimp's parser.
constexpr unsigned kMaxJsonDepth = 1000;

// The next `limit` bytes of `in` (a .glb's JSON chunk: its length), read in blocks, as the input
// stream RapidJSON reads: '\0' at the end, as Assimp's copy of the file ends. Parsing in place, as
// Assimp does, RapidJSON writes each string back into the stream; here those bytes are dropped.
class JsonStream {
public:
    using Ch = char;

    JsonStream(std::istream& in, std::uintmax_t limit) : in_(in), left_(limit) {}

    // NOLINTBEGIN(readability-identifier-naming): the names RapidJSON's streams have.
    Ch Peek() { return at_ != end_ || fill() ? *at_ : '\0'; }
    Ch Take() {
        const Ch c = Peek();
        at_ += at_ != end_ ? 1 : 0;
        return c;
    }
    std::size_t Tell() const { return before_ + static_cast<std::size_t>(at_ - buffer_.data()); }
    Ch* PutBegin() {
        put_ = 0;
        return nullptr;
    }
    void Put(Ch /*c*/) { ++put_; }
    std::size_t PutEnd(const Ch* /*begin*/) const { return put_; }
    // NOLINTEND(readability-identifier-naming)

    /// Whether all the bytes have been taken (a 0 byte before that is not the end).
    bool at_end() { return at_ == end_ && !fill(); }

private:
    bool fill() {
        before_ += static_cast<std::size_t>(end_ - buffer_.data());
        in_.read(buffer_.data(), static_cast<std::streamsize>(std::min<std::uintmax_t>(
                                     left_, static_cast<std::uintmax_t>(buffer_.size()))));
        const auto got = static_cast<std::size_t>(in_.gcount());
        left_ -= got;
        at_ = buffer_.data();
        end_ = at_ + got;
        return got > 0;
    }

    std::istream& in_;
    std::uintmax_t left_;
    std::vector<char> buffer_ = std::vector<char>(std::size_t{1} << 16);
    const char* at_ = buffer_.data();
    const char* end_ = buffer_.data();
    std::size_t before_ = 0;  // the bytes of the blocks before this one
    std::size_t put_ = 0;
};

// Refuses arrays and objects nested deeper than kMaxJsonDepth; takes every other value.
class DepthLimit : public rapidjson::BaseReaderHandler<rapidjson::UTF8<>, DepthLimit> {
public:
    // NOLINTBEGIN(readability-identifier-naming): the names RapidJSON's handlers have.
    bool StartObject() { return ++depth_ <= kMaxJsonDepth; }
    bool StartArray() { return ++depth_ <= kMaxJsonDepth; }
    bool EndObject(rapidjson::SizeType /*members*/) {
        --depth_;
        return true;
    }
    bool EndArray(rapidjson::SizeType /*elements*/) {
        --depth_;
        return true;
    }
    // NOLINTEND(readability-identifier-naming)

private:
    unsigned depth_ = 0;
};

// The text about a fault's offset, read again.
struct Around {
    int line = 1;
    char last = 0;        // the byte before the offset
    char last_solid = 0;  // the last byte before it that is not a blank
    std::string letters;  // the ASCII letters right before it (a word cut short: 'tru')
    std::string ahead;    // up to 48 bytes from it; none at the end of the text
};

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool is_letter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

Around read_around(JsonStream& json, std::size_t offset) {
    Around a;
    while (json.Tell() < offset && !json.at_end()) {
        const char c = json.Take();
        a.line += a.last == '\n' ? 1 : 0;
        a.last = c;
        a.last_solid = is_blank(c) ? a.last_solid : c;
        if (!is_letter(c)) {
            a.letters.clear();
        } else if (a.letters.size() < 40) {
            a.letters.push_back(c);
        }
    }
    while (a.ahead.size() < 48 && !json.at_end()) {
        a.ahead.push_back(json.Take());
    }
    // The offset's line; at the end, the last byte's.
    a.line += a.last == '\n' && !a.ahead.empty() ? 1 : 0;
    return a;
}

// The byte at `at` in `ahead`, named for a message.
std::string describe(const std::string& ahead, std::size_t at, bool chunk) {
    if (at >= ahead.size()) {
        return chunk ? "the end of the JSON chunk" : "end of file";
    }
    const auto c = static_cast<unsigned char>(ahead[at]);
    if (c == '\n') {
        return "a line break";
    }
    return c >= 0x20 && c < 0x7f ? fmt::format("'{}'", static_cast<char>(c))
                                 : fmt::format("byte 0x{:02x}", c);
}

// The byte after the "\uXXXX" escapes starting `ahead` that is not a hex digit.
std::size_t first_non_hex(const std::string& ahead) {
    std::size_t at = 0;
    while (ahead.compare(at, 2, "\\u") == 0) {
        at += 2;
        for (int i = 0; i < 4; ++i, ++at) {
            if (at >= ahead.size() || std::isxdigit(static_cast<unsigned char>(ahead[at])) == 0) {
                return at;
            }
        }
    }
    return at;
}

// What RapidJSON's fault `code` expected, and what it found, from the text about it.
std::pair<std::string, std::string> explain(rapidjson::ParseErrorCode code, const Around& a,
                                            bool chunk) {
    using namespace rapidjson;
    const std::string found = describe(a.ahead, 0, chunk);
    switch (code) {
        case kParseErrorDocumentEmpty:  // also a first value that is not an object
            if (a.ahead.compare(0, 3, "\xef\xbb\xbf") == 0) {
                return {"'{' to start the glTF object",
                        "a UTF-8 byte order mark (Assimp's parser reads JSON without one)"};
            }
            return {"'{' to start the glTF object", found};
        case kParseErrorDocumentRootNotSingular:
            return {chunk ? "the end of the JSON chunk after the glTF object"
                          : "the end of the file after the glTF object",
                    found};
        case kParseErrorValueInvalid: {
            if (a.last == '-') {
                return {"a digit in the number", found};
            }
            std::string word = a.letters;
            for (std::size_t i = 0; i < a.ahead.size() && is_letter(a.ahead[i]); ++i) {
                word.push_back(a.ahead[i]);
            }
            return {"a value", word.empty() ? found : quote_token(word)};
        }
        case kParseErrorObjectMissName:
            return {
                a.last_solid == '{' ? "a member name in quotes or '}'" : "a member name in quotes",
                found};
        case kParseErrorObjectMissColon:
            return {"':' after the member name", found};
        case kParseErrorObjectMissCommaOrCurlyBracket:
            return {"',' or '}' in an object", found};
        case kParseErrorArrayMissCommaOrSquareBracket:
            return {"',' or ']' in an array", found};
        case kParseErrorStringUnicodeEscapeInvalidHex:  // at the escape's '\'
            return {"4 hex digits after '\\u'", describe(a.ahead, first_non_hex(a.ahead), chunk)};
        case kParseErrorStringUnicodeSurrogateInvalid:  // at the first half's '\'
            return {"'\\u' and a low surrogate (DC00 to DFFF) after a high one (D800 to DBFF)",
                    a.ahead.compare(6, 2, "\\u") == 0 ? quote_token(a.ahead.substr(6, 6))
                                                      : describe(a.ahead, 6, chunk)};
        case kParseErrorStringEscapeInvalid:  // at the escape's '\', or at a control byte
            if (!a.ahead.empty() && a.ahead[0] == '\\') {
                return {"one of \" \\ / b f n r t u after '\\'", describe(a.ahead, 1, chunk)};
            }
            return {"'\"' to end the string", found};
        case kParseErrorStringMissQuotationMark:
            return {"'\"' to end the string", found};
        case kParseErrorNumberTooBig: {  // at the number's start
            const std::size_t length = a.ahead.find_first_not_of("+-.0123456789eE");
            return {"a number within a double's range", quote_token(a.ahead.substr(0, length))};
        }
        case kParseErrorNumberMissFraction:
            return {"a digit after the decimal point", found};
        case kParseErrorNumberMissExponent:
            return {"a digit in the exponent", found};
        default:
            return {"JSON", found};
    }
}

// The check of one text: the bytes of `in` from where it stands.
class GltfJson {
public:
    GltfJson(std::istream& in, std::uintmax_t bytes, const std::string& name, bool chunk)
        : in_(in), start_(in.tellg()), bytes_(bytes), name_(name), chunk_(chunk) {}

    void check() {
        JsonStream json(in_, bytes_);
        while (is_blank(json.Peek())) {
            json.Take();
        }
        if (json.Peek() != '{') {
            fail(json.Tell(), rapidjson::kParseErrorDocumentEmpty);
        }
        DepthLimit depth;
        rapidjson::Reader reader;
        // Iterative: RapidJSON's recursion (Assimp's) overflowed the stack at 300,000 levels.
        const rapidjson::ParseResult result =
            reader.Parse<rapidjson::kParseIterativeFlag | rapidjson::kParseInsituFlag>(json, depth);
        if (result.IsError()) {
            fail(result.Offset(), result.Code());
        }
    }

private:
    [[noreturn]] void fail(std::size_t offset, rapidjson::ParseErrorCode code) {
        in_.clear();
        in_.seekg(start_);
        JsonStream again(in_, bytes_);
        const Around a = read_around(again, offset);
        std::string message;
        if (code == rapidjson::kParseErrorTermination) {  // only DepthLimit stops it
            message =
                fmt::format("the JSON's arrays and objects nest more than {} deep", kMaxJsonDepth);
        } else {
            const auto [expected, found] = explain(code, a, chunk_);
            message = fmt::format("expected {}, found {}", expected, found);
        }
        if (chunk_) {
            throw InputError({name_, 0, 0},
                             fmt::format("line {} of the JSON chunk: {}", a.line, message));
        }
        throw InputError({name_, a.line, 0}, message);
    }

    std::istream& in_;
    std::istream::pos_type start_;
    std::uintmax_t bytes_;
    const std::string& name_;
    bool chunk_;
};

}  // namespace

void check_gltf_json(std::istream& in, std::uintmax_t bytes, const std::string& name, bool chunk) {
    GltfJson(in, bytes, name, chunk).check();
}

}  // namespace rt
