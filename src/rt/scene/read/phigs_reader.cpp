#include "rt/scene/read/phigs_reader.h"

#include <algorithm>

#include "rt/scene/read/reader_limits.h"
#include "rt/scene/read/word_stream.h"

#include <fmt/format.h>

namespace rt {

namespace {

constexpr std::string_view kRecord = "FILL_AREA_SET_3_WITH_DATA";

class PhigsReader {
public:
    PhigsReader(const SourceText& source, Diagnostics& diagnostics)
        : in_(source, WordLexerOptions{.hash_comments = true}), diagnostics_(diagnostics) {}

    SurfaceMesh read() {
        while (const auto word = in_.lexer().peek()) {
            if (std::ssize(mesh_.polygons) >= kMaxItemsPerFile) {
                throw InputError(location_of(in_.source(), *word),
                                 fmt::format("more than {} fill areas", kMaxItemsPerFile));
            }
            in_.expect(kRecord, std::string(kRecord));
            read_record(word->line);
        }
        return std::move(mesh_);
    }

private:
    void read_record(int line);
    std::vector<std::uint32_t> read_boundary(const std::string& name);

    WordStream in_;
    Diagnostics& diagnostics_;
    SurfaceMesh mesh_;
};

void PhigsReader::read_record(int line) {
    const std::string name = fmt::format("fill area {}", mesh_.polygons.size());
    MeshPolygon p;
    p.number = static_cast<long>(mesh_.polygons.size());
    p.line = line;
    bool has_normal = false;
    bool has_offset = false;
    std::vector<std::uint32_t> loop;
    bool has_boundary = false;
    const std::string what = "FACET_NORMAL, ATTRIBUTE_OFFSET, BOUNDARY or END in " + name;
    for (Token t = in_.take(what); t.text != "END"; t = in_.take(what)) {
        const SourceLocation at = location_of(in_.source(), t);
        const auto once = [&](bool& seen) {
            if (seen) {
                throw InputError(at, fmt::format("{} has a second {}", name, t.text));
            }
            seen = true;
        };
        if (t.text == "FACET_NORMAL") {
            once(has_normal);
            p.outward = in_.point("the facet normal of " + name);
        } else if (t.text == "ATTRIBUTE_OFFSET") {
            once(has_offset);
            p.attribute_offset = static_cast<long>(in_.integer("the attribute offset of " + name));
        } else if (t.text == "BOUNDARY") {
            if (has_boundary) {
                throw InputError(at, name +
                                         " has a second BOUNDARY: holes are not supported; "
                                         "write one record per polygon");
            }
            has_boundary = true;
            loop = read_boundary(name);
        } else {
            throw expected_found(at, what, quote_token(t.text));
        }
    }
    if (!has_boundary) {
        throw InputError(in_.source().at(line), name + " has no BOUNDARY");
    }
    mesh_.add_polygon(p, loop);
    if (diagnostics_.tracing()) {
        diagnostics_.trace(fmt::format("{}: {}: {} corners, facet normal {}, attribute offset {}",
                                       in_.source().at(line).to_string(), name, loop.size(),
                                       show_point(p.outward.x, p.outward.y, p.outward.z),
                                       p.attribute_offset));
    }
}

// PHIGS lists each fill area's corners in place; they become vertices of their own.
std::vector<std::uint32_t> PhigsReader::read_boundary(const std::string& name) {
    const std::int64_t n = in_.count("the corner count of " + name, kMaxEdgesPerPolygon);
    if (std::ssize(mesh_.vertices) + n > kMaxItemsPerFile) {
        throw InputError(in_.source().at(in_.lexer().line()),
                         fmt::format("more than {} corners in the file", kMaxItemsPerFile));
    }
    std::vector<std::uint32_t> loop;
    loop.reserve(static_cast<std::size_t>(std::min(n, in_.lexer().max_words_left() / 3 + 1)));
    for (std::int64_t k = 0; k < n; ++k) {
        loop.push_back(static_cast<std::uint32_t>(mesh_.vertices.size()));
        mesh_.vertices.push_back(in_.point(fmt::format("corner {} of {}", k + 1, name)));
        mesh_.vertex_lines.push_back(in_.lexer().line());  // the line of the corner's z
    }
    return loop;
}

}  // namespace

SurfaceMesh read_phigs_file(const SourceText& source, Diagnostics& diagnostics) {
    return PhigsReader(source, diagnostics).read();
}

}  // namespace rt
