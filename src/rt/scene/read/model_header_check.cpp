#include "rt/scene/read/model_header_check.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"
#include "rt/scene/read/line_words.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

// The words of one of the header's few lines, as strings.
std::vector<std::string> words_of(std::string_view line) {
    std::vector<std::string_view> views;
    split_words(line, views);
    return {views.begin(), views.end()};
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

bool is_integer_type(const std::string& type) {
    return type != "float" && type != "float32" && type != "double" && type != "float64";
}

bool is_signed_type(const std::string& type) {
    return type == "char" || type == "int8" || type == "short" || type == "int16" ||
           type == "int" || type == "int32";
}

// One PLY property as the body walk needs it: a scalar's size, or a list's count and item types.
struct PlyProperty {
    std::string name;
    bool list = false;
    std::string count_type;  ///< a list's count type
    std::uintmax_t count_bytes = 0;
    bool count_signed = false;
    std::string type;          ///< a scalar's type, or a list item's
    std::uintmax_t bytes = 0;  ///< a scalar's size, or a list item's
    /// What the type names say, found once: asked of every face by comparing names, they took
    /// 40 ms of a million-face model's load.
    bool type_signed = false;
    bool type_integer = false;
    bool vertex_numbers = false;  ///< a face's list of vertex numbers, as Assimp reads it
};

struct PlyLayout {
    enum class Format { Ascii, LittleEndian, BigEndian } format = Format::Ascii;
    struct Element {
        std::string name;
        std::int64_t count = 0;
        std::vector<PlyProperty> properties;
    };
    std::vector<Element> elements;
    std::int64_t vertices = -1;  ///< the vertex element's count; -1 without one
    std::uintmax_t header_bytes = 0;
    int header_lines = 0;
};

// The header's layout; false when the file is not PLY or its header is not whole (the header
// check and Assimp say why).
bool read_ply_layout(std::istream& in, PlyLayout& layout) {
    std::string text;
    if (!std::getline(in, text) || (!text.starts_with("ply") && !text.starts_with("PLY"))) {
        return false;
    }
    layout.header_bytes = text.size() + 1;
    layout.header_lines = 1;
    while (std::getline(in, text) && !in.eof()) {
        layout.header_bytes += text.size() + 1;
        ++layout.header_lines;
        const std::vector<std::string> w = words_of(text);
        if (w.empty()) {
            continue;
        }
        if (w[0] == "end_header") {
            for (const PlyLayout::Element& e : layout.elements) {
                layout.vertices = e.name == "vertex" ? e.count : layout.vertices;
            }
            return true;
        }
        if (w[0] == "format" && w.size() >= 2) {
            layout.format = w[1] == "binary_little_endian" ? PlyLayout::Format::LittleEndian
                            : w[1] == "binary_big_endian"  ? PlyLayout::Format::BigEndian
                                                           : PlyLayout::Format::Ascii;
        } else if (w[0] == "element" && w.size() >= 3) {
            const std::optional<std::int64_t> count = parse_integer(w[2]);
            layout.elements.push_back({w[1], count.value_or(0), {}});
        } else if (w[0] == "property" && w.size() >= 3 && !layout.elements.empty()) {
            PlyProperty p;
            p.name = w.back();
            p.list = w[1] == "list" && w.size() >= 5;
            p.count_type = p.list ? w[2] : "";
            p.count_bytes = p.list ? binary_size(w[2]) : 0;
            p.count_signed = p.list && is_signed_type(p.count_type);
            p.type = p.list ? w[3] : w[1];
            p.bytes = binary_size(p.type);
            p.type_signed = is_signed_type(p.type);
            p.type_integer = is_integer_type(p.type);
            // The face list Assimp takes the polygons' corners from (its PLY parser's names).
            p.vertex_numbers = p.list && layout.elements.back().name == "face" &&
                               (p.name == "vertex_indices" || p.name == "vertex_index");
            layout.elements.back().properties.push_back(p);
        }
    }
    return false;
}

// An integer of a binary PLY (a list count, or a vertex number): `bytes` long (1 to 8), signed or
// unsigned, in either byte order.
std::int64_t binary_integer(const unsigned char* b, std::uintmax_t bytes, bool is_signed,
                            bool big_endian) {
    std::uint64_t raw = 0;
    for (std::uintmax_t i = 0; i < bytes; ++i) {
        const std::uintmax_t k = big_endian ? i : bytes - 1 - i;
        raw = (raw << 8) | b[k];
    }
    if (is_signed && bytes > 0 && bytes < 8 && (raw >> (8 * bytes - 1)) != 0) {
        return static_cast<std::int64_t>(raw) - (std::int64_t{1} << (8 * bytes));
    }
    return static_cast<std::int64_t>(raw);
}

// Reads a binary file forward in big blocks.
class ByteWalk {
public:
    /// The buffer's room is reserved once: a block plus what one take() may keep from the last
    /// (n <= 8), so it never moves. Growing, it moved twice into fresh memory.
    explicit ByteWalk(std::istream& in) : in_(in) { buffer_.reserve(kBlock + 8); }
    /// The next `n` bytes (n <= 8), or null at the end of the file.
    const unsigned char* take(std::uintmax_t n) {
        if (!fill(n)) {
            return nullptr;
        }
        const unsigned char* at = buffer_.data() + next_;
        next_ += n;
        return at;
    }
    /// Skips `n` bytes; false if the file ends first.
    bool skip(std::uintmax_t n) {
        const std::uintmax_t here = std::min<std::uintmax_t>(n, buffer_.size() - next_);
        next_ += here;
        n -= here;
        if (n == 0) {
            return true;
        }
        in_.seekg(static_cast<std::streamoff>(n - 1), std::ios::cur);
        return static_cast<bool>(in_) && in_.get() != std::char_traits<char>::eof();
    }

private:
    bool fill(std::uintmax_t n) {
        if (buffer_.size() - next_ >= n) {
            return true;
        }
        buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(next_));
        next_ = 0;
        const std::size_t kept = buffer_.size();
        buffer_.resize(kept + kBlock);
        in_.read(reinterpret_cast<char*>(buffer_.data() + kept),
                 static_cast<std::streamsize>(kBlock));
        buffer_.resize(kept + static_cast<std::size_t>(in_.gcount()));
        return buffer_.size() >= n;
    }

    static constexpr std::size_t kBlock = std::size_t{1} << 20;
    std::istream& in_;
    std::vector<unsigned char> buffer_;
    std::size_t next_ = 0;
};

std::string ply_list_fault(const PlyLayout::Element& e, std::int64_t index, std::int64_t count) {
    return fmt::format("{} element {} has a list of {} items: expected 0 to {}", e.name, index,
                       count, kMaxEdgesPerPolygon);
}

// Assimp reads a face's vertex numbers as unsigned: -5 would be named as vertex 4294967291.
std::string ply_vertex_fault(std::int64_t face, std::string_view vertex, std::int64_t vertices) {
    if (vertices == 0) {
        return fmt::format("face element {} refers to vertex {}, but the file has no vertices",
                           face, vertex);
    }
    return fmt::format("face element {} refers to vertex {}: expected 0 to {}", face, vertex,
                       vertices - 1);
}

std::string ply_truncated(const PlyLayout::Element& e, std::int64_t index) {
    return fmt::format(
        "the file ends in {} element {} of the {} its header promises (the file "
        "is truncated or its header is wrong)",
        e.name, index, e.count);
}

// A face's `n` vertex numbers, read as their type says; false if the file ends first.
bool walk_binary_vertex_numbers(ByteWalk& bytes, const PlyProperty& p, std::int64_t n,
                                std::int64_t face, const PlyLayout& layout,
                                const std::string& name) {
    const bool big_endian = layout.format == PlyLayout::Format::BigEndian;
    for (std::int64_t k = 0; k < n; ++k) {
        const unsigned char* at = bytes.take(p.bytes);
        if (at == nullptr) {
            return false;
        }
        const std::int64_t v = binary_integer(at, p.bytes, p.type_signed, big_endian);
        if (v < 0 || v >= layout.vertices) {
            throw InputError({name, 0, 0},
                             ply_vertex_fault(face, std::to_string(v), layout.vertices));
        }
    }
    return true;
}

// One element with lists, its list counts (and a face's vertex numbers) read and checked, the rest
// skipped.
void walk_binary_element(ByteWalk& bytes, const PlyLayout::Element& e, std::int64_t i,
                         const PlyLayout& layout, const std::string& name) {
    const bool big_endian = layout.format == PlyLayout::Format::BigEndian;
    for (const PlyProperty& p : e.properties) {
        std::uintmax_t skip = p.bytes;
        if (p.list) {
            const unsigned char* at = bytes.take(p.count_bytes);
            if (at == nullptr) {
                throw InputError({name, 0, 0}, ply_truncated(e, i));
            }
            const std::int64_t n = binary_integer(at, p.count_bytes, p.count_signed, big_endian);
            if (n < 0 || n > kMaxEdgesPerPolygon) {
                throw InputError({name, 0, 0}, ply_list_fault(e, i, n));
            }
            skip = static_cast<std::uintmax_t>(n) * p.bytes;
            // (A float type's numbers Assimp rounds: left to it.)
            if (p.vertex_numbers && layout.vertices >= 0 && p.type_integer) {
                if (!walk_binary_vertex_numbers(bytes, p, n, i, layout, name)) {
                    throw InputError({name, 0, 0}, ply_truncated(e, i));
                }
                skip = 0;
            }
        }
        if (!bytes.skip(skip)) {
            throw InputError({name, 0, 0}, ply_truncated(e, i));
        }
    }
}

void walk_binary_ply(std::istream& in, const PlyLayout& layout, const std::string& name) {
    ByteWalk bytes(in);
    for (const PlyLayout::Element& e : layout.elements) {
        // Elements without lists (the vertices, mostly) have one size: skipped whole.
        std::uintmax_t record = 0;
        bool lists = false;
        for (const PlyProperty& p : e.properties) {
            record += p.bytes;
            lists = lists || p.list;
        }
        if (!lists && !bytes.skip(static_cast<std::uintmax_t>(e.count) * record)) {
            throw InputError({name, 0, 0}, ply_truncated(e, e.count - 1));
        }
        for (std::int64_t i = 0; lists && i < e.count; ++i) {
            walk_binary_element(bytes, e, i, layout, name);
        }
    }
}

// A face's vertex numbers on its line (the words from `first`, as many as there are up to `n`).
void check_ascii_vertex_numbers(const std::vector<std::string_view>& w, std::size_t first,
                                std::int64_t n, std::int64_t face, std::int64_t vertices,
                                const SourceLocation& at) {
    const std::size_t end = std::min(w.size(), first + static_cast<std::size_t>(n));
    for (std::size_t k = first; k < end; ++k) {
        const std::optional<std::int64_t> v = parse_integer(w[k]);
        if (!v || *v < 0 || *v >= vertices) {
            throw InputError(at, ply_vertex_fault(face, v ? w[k] : quote_token(w[k]), vertices));
        }
    }
}

// The words element `i` of `e` takes on its line: each scalar one, each list its count and as many
// items; an error at the line for a count out of range, or a face's vertex number the file does
// not have.
std::size_t ascii_element_words(const std::vector<std::string_view>& w, const PlyLayout::Element& e,
                                std::int64_t i, std::int64_t vertices, const SourceLocation& at) {
    std::size_t next = 0;
    for (const PlyProperty& p : e.properties) {
        std::int64_t items = 1;
        if (p.list && next < w.size()) {
            const std::optional<std::int64_t> n = parse_integer(w[next++]);
            if (!n || *n < 0 || *n > kMaxEdgesPerPolygon) {
                throw expected_found(at,
                                     fmt::format("the list count of {} element {} (0 to {})",
                                                 e.name, i, kMaxEdgesPerPolygon),
                                     quote_token(w[next - 1]));
            }
            items = *n;
            if (p.vertex_numbers && vertices >= 0) {
                check_ascii_vertex_numbers(w, next, items, i, vertices, at);
            }
        }
        next += static_cast<std::size_t>(items);
    }
    return next;
}

// In ASCII each element is one line (blank lines apart): its words must be exactly its properties,
// a list's count followed by as many items.
void walk_ascii_ply(std::istream& in, const PlyLayout& layout, const std::string& name) {
    int line = layout.header_lines;
    std::string text;
    std::vector<std::string_view> w;
    for (const PlyLayout::Element& e : layout.elements) {
        for (std::int64_t i = 0; i < e.count; ++i) {
            w.clear();
            while (w.empty()) {
                if (!std::getline(in, text)) {
                    throw InputError({name, line, 0}, ply_truncated(e, i));
                }
                ++line;
                split_words(text, w);
            }
            const std::size_t needed =
                ascii_element_words(w, e, i, layout.vertices, {name, line, 0});
            if (needed != w.size()) {
                throw expected_found({name, line, 0},
                                     fmt::format("{} numbers in {} element {} (as the header "
                                                 "lays it out)",
                                                 needed, e.name, i),
                                     std::to_string(w.size()));
            }
        }
    }
}

// The face lines in the bytes given (the file's start): each must start with its corner count, a
// whole number from 1, followed by as many vertex numbers, each one the file has. A few lines that
// are not faces make Assimp 5.2's OFF reader read past its faces (a crash found by fuzzing,
// docs/lab/fuzz-2026-12-02.md); a number out of range it clamps. When the bytes are the whole
// file (`whole`), it must hold the vertices and faces its header promises: Assimp makes up the
// rest with a warning.
void check_off_faces(std::istream& in, int line, std::int64_t vertices, std::int64_t faces,
                     bool whole, const std::string& name) {
    std::int64_t vertex_lines = 0;
    std::int64_t face_lines = 0;
    for (std::string text; face_lines < faces && std::getline(in, text);) {
        ++line;
        if (in.eof() && !whole) {
            return;  // a last line cut off at the end of the bytes given
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
            good = v && *v >= 0 && *v < vertices;
        }
        if (!good) {
            throw InputError({name, line, 0},
                             fmt::format("expected face {}: a corner count from 1, then as many "
                                         "vertex numbers (0 to {}); found '{}'",
                                         face_lines - 1, vertices - 1, text));
        }
    }
    if (whole && face_lines < faces) {
        const bool short_of_vertices = vertex_lines < vertices;
        throw InputError({name, std::max(line, 1), 0},
                         fmt::format("the file ends after {} of the {} {} its header promises (the "
                                     "file is truncated or its header is wrong)",
                                     short_of_vertices ? vertex_lines : face_lines,
                                     short_of_vertices ? vertices : faces,
                                     short_of_vertices ? "vertices" : "faces"));
    }
}

}  // namespace

void check_ply_body(const std::filesystem::path& path, const std::string& name) {
    std::ifstream in(path, std::ios::binary);
    PlyLayout layout;
    if (!in || !read_ply_layout(in, layout)) {
        return;
    }
    for (const PlyLayout::Element& e : layout.elements) {
        for (const PlyProperty& p : e.properties) {
            if (layout.format != PlyLayout::Format::Ascii &&
                (p.bytes == 0 || (p.list && p.count_bytes == 0))) {
                return;  // a type PLY does not have: Assimp refuses the header
            }
        }
    }
    for (const PlyLayout::Element& e : layout.elements) {
        if (e.name != "vertex") {
            continue;
        }
        for (const char* axis : {"x", "y", "z"}) {
            if (std::none_of(e.properties.begin(), e.properties.end(),
                             [&](const PlyProperty& p) { return p.name == axis && !p.list; })) {
                throw InputError({name, 0, 0},
                                 fmt::format("the vertex element has no property {}", axis));
            }
        }
    }
    if (layout.format == PlyLayout::Format::Ascii) {
        walk_ascii_ply(in, layout, name);
    } else {
        walk_binary_ply(in, layout, name);
    }
}

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
    check_off_faces(in, line, *vertices, *faces, bytes.size() >= file_size, name);
}

}  // namespace rt
