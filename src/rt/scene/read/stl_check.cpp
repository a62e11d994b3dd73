#include "rt/scene/read/stl_check.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"
#include "rt/scene/read/line_words.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

constexpr std::uintmax_t kStlHeaderBytes = 84;  // an 80-byte header, then the 4-byte count
constexpr std::uintmax_t kStlTriangleBytes = 50;
// A count that matches the file's size is within the item limit: no binary STL that rt reads asks
// Assimp for more triangles than that.
static_assert(kMaxInputFileBytes / kStlTriangleBytes < kMaxItemsPerFile);

std::string lower(std::string_view word) {
    std::string out(word);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

// A binary STL shows in its first bytes: its count's high byte is 0 below 2^24 triangles, and its
// floats hold bytes below 32. Text has none but blanks (and an old DOS end-of-file mark).
bool looks_binary(std::string_view head) {
    return std::any_of(head.begin(), head.end(), [](char c) {
        const auto b = static_cast<unsigned char>(c);
        return b < 0x20 && std::isspace(b) == 0 && b != 0x1a;
    });
}

// The first word of the first line, after blanks: Assimp takes a file as ASCII when it starts
// with "solid".
std::string_view first_word(std::string_view head) {
    const std::size_t start = std::min(head.find_first_not_of(" \t"), head.size());
    const std::size_t end = std::min(head.find_first_of(" \t\r\n\f\v", start), head.size());
    return head.substr(start, end - start);
}

// A number as Assimp's reader takes one: a decimal, or nan or inf (a normal of a degenerate
// facet; a coordinate that is no number the mesh check refuses).
bool stl_number(std::string_view word) {
    if (parse_double(word)) {
        return true;
    }
    if (!word.empty() && (word.front() == '-' || word.front() == '+')) {
        word.remove_prefix(1);
    }
    const std::string w = lower(word);
    return w == "nan" || w == "inf" || w == "infinity";
}

// The words of an ASCII STL one after another, with their lines: the file is streamed and
// nothing is kept, so the walk costs little beside Assimp's read.
class StlWords {
public:
    explicit StlWords(std::istream& in) : in_(in) {}
    /// The next word, without taking it; empty at the end of the file.
    std::string_view peek() {
        while (at_ == words_.size()) {
            if (!std::getline(in_, text_)) {
                return {};
            }
            ++line_;
            split_words(text_, words_);
            at_ = 0;
        }
        return words_[at_];
    }
    std::string_view next() {
        const std::string_view word = peek();
        at_ += word.empty() ? 0 : 1;
        return word;
    }
    /// Drops the rest of the line (after endsolid, as Assimp does).
    void skip_line() { at_ = words_.size(); }
    /// Drops the rest of the line up to a word that starts a facet or ends the solid: a solid's
    /// name may have blanks ("solid Mesh 1"), and a file may be one line.
    void skip_name() {
        while (at_ < words_.size() && words_[at_] != "facet" &&
               !words_[at_].starts_with("endsolid")) {
            ++at_;
        }
    }
    int line() const { return std::max(line_, 1); }

private:
    std::istream& in_;
    std::string text_;
    std::vector<std::string_view> words_;
    std::size_t at_ = 0;
    int line_ = 0;
};

// The walk over the words, in the order Assimp looks for them (it needs only facet normal and
// vertex, but a file without the rest is not STL, or is cut short).
class StlWalk {
public:
    StlWalk(std::istream& in, const std::string& name) : words_(in), name_(name) {}

    /// The solids one after another (a file may hold several); Assimp ignores what follows the
    /// last one, and so does the walk.
    void solids() {
        do {
            solid();
        } while (words_.peek().starts_with("solid"));
    }

private:
    void solid() {
        words_.next();
        words_.skip_name();
        for (std::string_view w = words_.next(); !w.starts_with("endsolid"); w = words_.next()) {
            if (w != "facet") {
                fail("'facet' or 'endsolid'", w);
            }
            facet();
        }
        words_.skip_line();
    }

    // After "facet". Assimp reads more than 3 vertices as the first 3 and logs an error (a
    // warning here).
    void facet() {
        keyword("normal");
        numbers("facet normal");
        keyword("outer");
        keyword("loop");
        int vertices = 0;
        for (std::string_view w = words_.next(); vertices < 3 || w != "endloop";
             w = words_.next()) {
            if (w != "vertex") {
                fail(vertices < 3 ? "'vertex'" : "'vertex' or 'endloop'", w);
            }
            numbers("vertex");
            ++vertices;
        }
        keyword("endfacet");
    }

    void keyword(std::string_view word) {
        const std::string_view w = words_.next();
        if (w != word) {
            fail(fmt::format("'{}'", word), w);
        }
    }

    void numbers(std::string_view after) {
        for (int i = 0; i < 3; ++i) {
            const std::string_view w = words_.next();
            if (!stl_number(w)) {
                fail(fmt::format("3 numbers after '{}'", after), w);
            }
        }
    }

    [[noreturn]] void fail(const std::string& expected, std::string_view found) {
        if (found.empty()) {
            throw expected_found({name_, words_.line(), 0}, expected, "end of file");
        }
        // Assimp 5.2 compares keywords as written: "FACET" it skips, "SOLID" it cannot read.
        static constexpr std::array<std::string_view, 8> kKeywords = {
            "facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet", "endsolid"};
        const std::string low = lower(found);
        const bool other_case =
            low != found && std::find(kKeywords.begin(), kKeywords.end(), low) != kKeywords.end();
        throw expected_found(
            {name_, words_.line(), 0}, expected,
            quote_token(found) +
                (other_case ? " (Assimp reads STL keywords in lowercase only)" : ""));
    }

    StlWords words_;
    const std::string& name_;
};

// The triangle count after a binary STL's 80-byte header (`head` holds at least 84 bytes).
std::uint32_t binary_count(std::string_view head) {
    std::uint32_t count = 0;
    for (std::size_t i = 84; i-- > 80;) {  // little-endian
        count = (count << 8) | static_cast<unsigned char>(head[i]);
    }
    return count;
}

InputError binary_size_fault(std::uint32_t count, std::uintmax_t size, const std::string& name) {
    return {{name, 0, 0},
            fmt::format("a binary STL of {} triangles needs {} bytes (80-byte header, 4-byte "
                        "count, 50 bytes a triangle), found {}",
                        count, kStlHeaderBytes + kStlTriangleBytes * count, size)};
}

// A file Assimp takes as neither binary nor ASCII: what it lacks for either.
[[noreturn]] void refuse_storage(std::string_view head, std::uintmax_t size,
                                 const std::string& name) {
    const bool binary = looks_binary(head);
    const std::string_view word = first_word(head);
    if (!binary && lower(word).starts_with("solid")) {
        throw expected_found({name, 1, 0}, "'solid'",
                             quote_token(word) + " (Assimp reads STL keywords in lowercase only)");
    }
    if (size < kStlHeaderBytes) {
        throw InputError({name, 0, 0}, fmt::format("expected a binary STL of at least 84 bytes, or "
                                                   "an ASCII STL starting with 'solid', found {} "
                                                   "bytes",
                                                   size));
    }
    if (!binary) {
        throw expected_found({name, 1, 0}, "'solid' to start an ASCII STL",
                             word.empty() ? "a blank line" : quote_token(word));
    }
    throw binary_size_fault(binary_count(head), size, name);
}

}  // namespace

void check_stl(const std::filesystem::path& path, const std::string& name) {
    std::ifstream in(path, std::ios::binary);
    std::string head(512, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    const std::uintmax_t size = std::filesystem::file_size(path);
    if (size >= kStlHeaderBytes && head.size() >= kStlHeaderBytes) {
        const std::uint32_t count = binary_count(head);
        const std::uintmax_t needed = kStlHeaderBytes + kStlTriangleBytes * count;
        if (needed == size) {
            return;  // binary, as Assimp takes it
        }
        // Assimp 5.2 computes the size in 32 bits: a count whose size wraps round to the file's
        // makes it binary too, and too short for its triangles.
        if (static_cast<std::uint32_t>(needed) == size) {
            throw binary_size_fault(count, size, name);
        }
    }
    if (!first_word(head).starts_with("solid") || looks_binary(head)) {
        refuse_storage(head, size, name);
    }
    in.clear();
    in.seekg(0);
    StlWalk(in, name).solids();
}

}  // namespace rt
