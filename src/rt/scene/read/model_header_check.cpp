#include "rt/scene/read/model_header_check.h"

#include <sstream>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::vector<std::string> words_of(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) {
        words.push_back(w);
    }
    return words;
}

// Bytes of one binary PLY scalar; 0 for a type name PLY does not have.
std::uintmax_t binary_size(const std::string& type) {
    for (const char* t : {"char", "uchar", "int8", "uint8"}) {
        if (type == t) {
            return 1;
        }
    }
    for (const char* t : {"short", "ushort", "int16", "uint16"}) {
        if (type == t) {
            return 2;
        }
    }
    for (const char* t : {"int", "uint", "float", "int32", "uint32", "float32"}) {
        if (type == t) {
            return 4;
        }
    }
    return type == "double" || type == "float64" ? 8 : 0;
}

struct PlyElement {
    std::string name;
    std::int64_t count = 0;
    std::uintmax_t least_bytes = 0;  ///< the fewest bytes one element can take in the file
    int line = 0;
};

// The fewest bytes a property adds to an element: in ASCII a digit and a blank per number (a list
// at least its count), in binary the scalar's size (a list at least its count's size).
std::uintmax_t least_property_bytes(const std::vector<std::string>& words, bool ascii) {
    if (ascii) {
        return 2;
    }
    const bool list = words.size() >= 3 && words[1] == "list";
    return std::max<std::uintmax_t>(1, binary_size(list ? words[2] : words[1]));
}

void check_count(const std::string& name, int line, const std::string& what, std::int64_t count,
                 std::uintmax_t least_bytes, std::uintmax_t room) {
    if (count > kMaxItemsPerFile) {
        throw InputError({name, line, 0}, fmt::format("the header promises {} {}, more than the "
                                                      "limit of {}",
                                                      count, what, kMaxItemsPerFile));
    }
    const auto n = static_cast<std::uintmax_t>(count);
    if (least_bytes > 0 && n > room / least_bytes) {
        throw InputError({name, line, 0},
                         fmt::format("the header promises {} {}, but the {} bytes after it hold "
                                     "at most {} (the file is truncated or its header is wrong)",
                                     count, what, room, room / least_bytes));
    }
}

}  // namespace

void check_ply_header(std::string_view bytes, std::uintmax_t file_size, const std::string& name) {
    if (!bytes.starts_with("ply") && !bytes.starts_with("PLY")) {
        return;  // not PLY: Assimp says so
    }
    std::istringstream in{std::string(bytes)};
    std::vector<PlyElement> elements;
    bool ascii = true;
    int line = 0;
    std::uintmax_t header_bytes = 0;
    for (std::string text; std::getline(in, text);) {
        ++line;
        header_bytes += text.size() + 1;
        const std::vector<std::string> w = words_of(text);
        if (w.empty()) {
            continue;
        }
        if (w[0] == "end_header" && !in.eof()) {  // eof: no line break after it
            const std::uintmax_t room = file_size > header_bytes ? file_size - header_bytes : 0;
            std::uintmax_t used = 0;
            for (const PlyElement& e : elements) {
                check_count(name, e.line, e.name + " elements", e.count, e.least_bytes,
                            room - std::min(room, used));
                used += static_cast<std::uintmax_t>(e.count) * e.least_bytes;
            }
            return;
        }
        if (w[0] == "format" && w.size() >= 2) {
            ascii = w[1] == "ascii";
        } else if (w[0] == "element" && w.size() >= 3) {
            const std::optional<std::int64_t> count = parse_integer(w[2]);
            if (!count || *count < 0) {
                throw expected_found({name, line, 0}, "the count of the " + w[1] + " elements",
                                     quote_token(w[2]));
            }
            elements.push_back({w[1], *count, 0, line});
        } else if (w[0] == "property" && w.size() >= 2 && !elements.empty()) {
            elements.back().least_bytes += least_property_bytes(w, ascii);
        }
    }
    // Assimp 5.2 loops for ever on a header that never ends (or ends without a line break).
    throw InputError(
        {name, std::max(line, 1), 0},
        fmt::format(
            "the PLY header has no end_header line ending in a line break{}",
            bytes.size() < file_size ? fmt::format(" in its first {} bytes", bytes.size()) : ""));
}

namespace {

// The face lines in the bytes given (the file's start): each must start with its corner count, a
// whole number from 1, followed by as many whole numbers (the vertices). A few lines that are not
// faces make Assimp 5.2's OFF reader read past its faces (a crash found by fuzzing,
// docs/lab/fuzz-2026-12-02.md).
void check_off_faces(std::istream& in, int line, std::int64_t vertices, std::int64_t faces,
                     const std::string& name) {
    std::int64_t vertex_lines = 0;
    std::int64_t face_lines = 0;
    for (std::string text; face_lines < faces && std::getline(in, text);) {
        ++line;
        if (in.eof()) {
            return;  // a last line cut off at the end of the bytes given, or of the file
        }
        const std::vector<std::string> words = words_of(text.substr(0, text.find('#')));
        if (words.empty()) {
            continue;
        }
        if (vertex_lines < vertices) {
            ++vertex_lines;
            continue;
        }
        ++face_lines;
        const std::optional<std::int64_t> corners = parse_integer(words[0]);
        bool good = corners && *corners >= 1 && static_cast<std::uint64_t>(*corners) < words.size();
        for (std::size_t i = 1; good && i <= static_cast<std::size_t>(*corners); ++i) {
            const std::optional<std::int64_t> v = parse_integer(words[i]);
            good = v.has_value();  // one out of range Assimp clamps, with a warning
        }
        if (!good) {
            throw InputError({name, line, 0},
                             "expected face " + std::to_string(face_lines - 1) +
                                 ": a corner count from 1, then as many vertex numbers; found '" +
                                 text + "'");
        }
    }
}

}  // namespace

void check_off_header(std::string_view bytes, std::uintmax_t file_size, const std::string& name) {
    std::istringstream in{std::string(bytes)};
    int line = 0;
    std::vector<std::string> counts;
    int counts_line = 0;
    for (std::string text; counts.size() < 2 && std::getline(in, text);) {
        ++line;
        text = text.substr(0, text.find('#'));
        for (const std::string& w : words_of(text)) {
            if (counts.empty() && w.size() >= 3 && w.compare(w.size() - 3, 3, "OFF") == 0) {
                continue;  // OFF, COFF, NOFF, ...
            }
            if (counts.empty()) {
                counts_line = line;
            }
            counts.push_back(w);
        }
    }
    if (counts.size() < 2) {
        return;
    }
    const std::optional<std::int64_t> vertices = parse_integer(counts[0]);
    const std::optional<std::int64_t> faces = parse_integer(counts[1]);
    if (!vertices || !faces || *vertices < 0 || *faces < 0) {
        return;
    }
    // A vertex is at least three numbers ("0 0 0 "), a face at least its corner count ("0 ").
    check_count(name, counts_line, "vertices", *vertices, 6, file_size);
    check_count(name, counts_line, "faces", *faces, 2,
                file_size - std::min(file_size, static_cast<std::uintmax_t>(*vertices) * 6));
    check_off_faces(in, line, *vertices, *faces, name);
}

}  // namespace rt
