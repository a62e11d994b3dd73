#include "rt/image/gro_header.h"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"
#include "rt/image/gro_format.h"
#include "rt/image/image8.h"

#include <fmt/format.h>

namespace rt {

namespace {

// Limits that keep a binary or hostile file from being read as an endless header.
constexpr std::size_t kMaxLineLength = 4096;
constexpr int kMaxHeaderLines = 1000;

// Binary junk is quoted as '?' so an error message stays one printable line.
std::string printable(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7f) {
            c = '?';
        }
    }
    return quote_token(out);
}

class LineReader {
public:
    LineReader(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

    /// The next line without its newline; false at the end of the file.
    bool next(std::string& text) {
        text.clear();
        bool any = false;
        for (int c = in_.get(); c != std::char_traits<char>::eof(); c = in_.get()) {
            any = true;
            ++bytes_;
            if (c == '\n') {
                break;
            }
            // Header lines are text: a control byte is the pixels (or another binary file)
            // reached before the 'end' line, which says more than "a line too long" would.
            if (c < 0x20 && c != '\t' && c != '\r') {
                throw expected_found(next_location(), "a header line, or 'end' closing the header",
                                     "binary data");
            }
            if (text.size() >= kMaxLineLength) {
                throw expected_found(
                    next_location(),
                    fmt::format("a header line of at most {} characters", kMaxLineLength),
                    "a longer one");
            }
            text.push_back(static_cast<char>(c));
        }
        if (any) {
            ++line_;
        }
        return any;
    }

    SourceLocation location() const { return {file_, line_, 0}; }
    SourceLocation next_location() const { return {file_, line_ + 1, 0}; }
    int line() const { return line_; }
    std::uint64_t bytes() const { return bytes_; }

private:
    std::istream& in_;
    std::string file_;
    int line_ = 0;
    std::uint64_t bytes_ = 0;
};

std::vector<std::string_view> split_words(std::string_view text) {
    std::vector<std::string_view> words;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t space = std::min(text.find(' ', start), text.size());
        words.push_back(text.substr(start, space - start));
        start = space + 1;
    }
    return words;
}

// Exactly N whole numbers separated by single spaces, each fitting an int.
template <std::size_t N>
std::array<int, N> whole_numbers(std::string_view key, std::string_view value,
                                 const SourceLocation& where) {
    const std::vector<std::string_view> words = split_words(value);
    std::array<int, N> numbers{};
    const std::string expected =
        fmt::format("{} whole number{} after '{}'", N, N == 1 ? "" : "s", key);
    if (words.size() != N) {
        throw expected_found(where, expected, printable(value));
    }
    for (std::size_t i = 0; i < N; ++i) {
        const std::optional<std::int64_t> n = parse_integer(words[i]);
        if (!n || *n < -1000000000 || *n > 1000000000) {
            throw expected_found(where, expected, printable(words[i]));
        }
        numbers[i] = static_cast<int>(*n);
    }
    return numbers;
}

void read_view(GroHeader& h, std::string_view value, const SourceLocation& where) {
    const auto [width, height] = whole_numbers<2>("view", value, where);
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
        throw expected_found(where, fmt::format("a view of 1 to {} pixels a side", kMaxImageSide),
                             fmt::format("{} x {}", width, height));
    }
    h.view_width = width;
    h.view_height = height;
}

void read_window(GroHeader& h, std::string_view value, const SourceLocation& where) {
    const auto [left, top, right, bottom] = whole_numbers<4>("window", value, where);
    h.window = {left, top, right, bottom};
}

void read_first_finished_row(GroHeader& h, std::string_view value, const SourceLocation& where) {
    h.first_finished_row = whole_numbers<1>("first_finished_row", value, where)[0];
}

void read_multiplier(GroHeader& h, std::string_view value, const SourceLocation& where) {
    const std::optional<double> m = parse_double(value);
    if (!m || *m < 0.0) {
        throw expected_found(where, "a non-negative number after 'display_multiplier'",
                             printable(value));
    }
    h.mapping.multiplier = *m;
}

void read_clip(GroHeader& h, std::string_view value, const SourceLocation& where) {
    if (value != "on" && value != "off") {
        throw expected_found(where, "'on' or 'off' after 'display_clip'", printable(value));
    }
    h.mapping.clip = value == "on";
}

void read_pixels(GroHeader& /*h*/, std::string_view value, const SourceLocation& where) {
    if (value != kGroPixelEncoding) {
        throw expected_found(where, fmt::format("pixel encoding '{}'", kGroPixelEncoding),
                             printable(value));
    }
}

// Reads one provenance field.
template <std::string FilmProvenance::*field>
void read_text(GroHeader& h, std::string_view value, const SourceLocation& /*where*/) {
    h.provenance.*field = value;
}

// Reads one field of a part file's.
template <std::string FilmPart::*field>
void read_part(GroHeader& h, std::string_view value, const SourceLocation& /*where*/) {
    h.part.*field = value;
}

using KeyReader = void (*)(GroHeader&, std::string_view, const SourceLocation&);

struct KeySpec {
    std::string_view key;
    bool required;
    KeyReader read;
};

// Text fields are kept verbatim; they only describe the picture.
constexpr std::array kKeys = {
    KeySpec{"view", true, read_view},
    KeySpec{"window", true, read_window},
    KeySpec{"first_finished_row", true, read_first_finished_row},
    KeySpec{"pixels", true, read_pixels},
    KeySpec{"display_multiplier", false, read_multiplier},
    KeySpec{"display_clip", false, read_clip},
    KeySpec{"scene", false, read_text<&FilmProvenance::scene>},
    KeySpec{"switches", false, read_text<&FilmProvenance::switches>},
    KeySpec{"program", false, read_text<&FilmProvenance::program>},
    KeySpec{"created", false, read_text<&FilmProvenance::created>},
    KeySpec{"part", false, read_part<&FilmPart::part>},
    KeySpec{"arguments", false, read_text<&FilmProvenance::arguments>},
    KeySpec{"seed", false, read_text<&FilmProvenance::seed>},
    KeySpec{"inputs", false, read_text<&FilmProvenance::inputs>},
};

bool valid_key(std::string_view key) {
    if (key.empty()) {
        return false;
    }
    for (const char c : key) {
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) {
            return false;
        }
    }
    return true;
}

void read_magic(LineReader& lines, const std::string& file) {
    std::string text;
    const bool any = lines.next(text);
    const std::string_view prefix = kGroMagic.substr(0, kGroMagic.rfind(' ') + 1);  // "GRO rt "
    if (!any || text.rfind(prefix, 0) != 0) {
        throw expected_found({file, 1, 0}, fmt::format("'{}' (a .gro picture)", kGroMagic),
                             any ? printable(text) : "an empty file");
    }
    const std::string_view version = std::string_view(text).substr(prefix.size());
    if (version != kGroMagic.substr(prefix.size())) {
        throw expected_found({file, 1, 0},
                             fmt::format(".gro format version {}", kGroMagic.substr(prefix.size())),
                             "version " + printable(version));
    }
}

// The checks that need several keys, each reported at the line that is out of range.
void check_consistency(const GroHeader& h, const std::map<std::string, int, std::less<>>& seen,
                       const std::string& file) {
    const PixelRect& w = h.window;
    if (w.left < 0 || w.top < 0 || w.left > w.right || w.top > w.bottom ||
        w.right >= h.view_width || w.bottom >= h.view_height) {
        throw expected_found(
            {file, seen.at("window"), 0},
            fmt::format("a window 'left top right bottom' inside the {} x {} view (0 0 {} {})",
                        h.view_width, h.view_height, h.view_width - 1, h.view_height - 1),
            fmt::format("{} {} {} {}", w.left, w.top, w.right, w.bottom));
    }
    if (h.first_finished_row < w.top || h.first_finished_row > w.bottom + 1) {
        throw expected_found({file, seen.at("first_finished_row"), 0},
                             fmt::format("a first finished row from {} to {} (the window's top "
                                         "row to one past its bottom row)",
                                         w.top, w.bottom + 1),
                             std::to_string(h.first_finished_row));
    }
}

void check_required(const std::map<std::string, int, std::less<>>& seen,
                    const SourceLocation& end) {
    for (const KeySpec& spec : kKeys) {
        if (spec.required && seen.find(spec.key) == seen.end()) {
            throw expected_found(end, fmt::format("a '{}' line before 'end'", spec.key), "none");
        }
    }
}

}  // namespace

GroHeader read_gro_header(std::istream& in, const std::string& file) {
    LineReader lines(in, file);
    read_magic(lines, file);
    GroHeader header;
    std::map<std::string, int, std::less<>> seen;  // key -> its line
    std::string text;
    while (lines.next(text)) {
        if (text == "end") {
            check_required(seen, lines.location());
            check_consistency(header, seen, file);
            header.lines = lines.line();
            header.bytes = lines.bytes();
            return header;
        }
        if (lines.line() > kMaxHeaderLines) {
            throw expected_found(lines.location(),
                                 fmt::format("'end' within {} header lines", kMaxHeaderLines),
                                 "more");
        }
        const std::size_t space = std::min(text.find(' '), text.size());
        const std::string_view key = std::string_view(text).substr(0, space);
        const std::string_view value =
            space < text.size() ? std::string_view(text).substr(space + 1) : std::string_view();
        if (!valid_key(key)) {
            throw expected_found(lines.location(), "a 'key value' header line", printable(text));
        }
        const auto [previous, first_time] = seen.emplace(std::string(key), lines.line());
        if (!first_time) {
            throw expected_found(
                lines.location(),
                fmt::format("one '{}' line (the first is line {})", key, previous->second),
                "a second");
        }
        header.fields.emplace_back(key, value);
        for (const KeySpec& spec : kKeys) {
            if (spec.key == key) {
                spec.read(header, value, lines.location());
            }
        }
        // Unknown keys are skipped: a newer writer may add fields an older reader can ignore.
    }
    throw expected_found(lines.next_location(), "'end' closing the header", "the end of the file");
}

namespace {

std::string header_text(std::string_view value) {
    std::string out(value);
    for (char& c : out) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
            c = ' ';
        }
    }
    return out;
}

}  // namespace

std::string format_gro_header(const Film& film) {
    const PixelRect& w = film.window();
    const FilmProvenance& p = film.provenance;
    std::string text = std::string(kGroMagic) + "\n";
    text += fmt::format("view {} {}\n", film.view_width(), film.view_height());
    text += fmt::format("window {} {} {} {}\n", w.left, w.top, w.right, w.bottom);
    text += fmt::format("first_finished_row {}\n", film.first_finished_row());
    // fmt's shortest round-trip form, so the multiplier reads back exactly.
    text += fmt::format("display_multiplier {}\n", film.mapping.multiplier);
    text += fmt::format("display_clip {}\n", film.mapping.clip ? "on" : "off");
    text += "scene " + header_text(p.scene) + "\n";
    text += "switches " + header_text(p.switches) + "\n";
    text += "program " + header_text(p.program) + "\n";
    text += "created " + header_text(p.created) + "\n";
    // Written only when known, so that a film from elsewhere does not claim to be resumable.
    if (!p.arguments.empty()) {
        text += "arguments " + header_text(p.arguments) + "\n";
        text += "seed " + header_text(p.seed) + "\n";
        text += "inputs " + header_text(p.inputs) + "\n";
    }
    if (!film.part.part.empty()) {  // a part file (rt --tile), which merge joins
        text += "part " + header_text(film.part.part) + "\n";
    }
    text += fmt::format("pixels {}\n", kGroPixelEncoding);
    text += "end\n";
    return text;
}

}  // namespace rt
