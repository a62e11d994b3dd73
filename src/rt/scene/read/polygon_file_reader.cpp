#include "rt/scene/read/polygon_file_reader.h"

#include <algorithm>
#include <unordered_map>

#include "rt/scene/read/edge_loop.h"
#include "rt/scene/read/reader_limits.h"
#include "rt/scene/read/word_stream.h"

#include <fmt/format.h>

namespace rt {

namespace {

// Index numbers of one kind (vertex, edge, polygon) and where each was defined.
class IndexTable {
public:
    IndexTable(const char* kind, std::size_t expected) : kind_(kind) { slots_.reserve(expected); }

    void define(std::int64_t number, std::uint32_t slot, const SourceLocation& at) {
        const auto [it, fresh] = slots_.emplace(number, Entry{slot, at.line});
        if (!fresh) {
            throw InputError(at, fmt::format("{} {} is defined twice (first at line {})", kind_,
                                             number, it->second.line));
        }
    }
    std::uint32_t find(std::int64_t number, const SourceLocation& at,
                       const std::string& referrer) const {
        const auto it = slots_.find(number);
        if (it == slots_.end()) {
            throw InputError(at, fmt::format("{} refers to {} {}, which is not defined", referrer,
                                             kind_, number));
        }
        return it->second.slot;
    }

private:
    struct Entry {
        std::uint32_t slot;
        int line;
    };
    const char* kind_;
    std::unordered_map<std::int64_t, Entry> slots_;
};

class PolygonFileReader {
public:
    PolygonFileReader(const SourceText& source, bool marks, Diagnostics& diagnostics)
        : in_(source), marks_(marks), diagnostics_(diagnostics) {}

    SurfaceMesh read();

private:
    std::size_t reservation(std::int64_t count, std::int64_t words_each) {
        return static_cast<std::size_t>(
            std::min(count, in_.lexer().max_words_left() / words_each + 1));
    }
    void trace(int line, const std::string& text) {
        if (diagnostics_.tracing()) {
            diagnostics_.trace(in_.source().at(line).to_string() + ": " + text);
        }
    }
    std::int64_t take_index(const std::string& what, SourceLocation& at) {
        const Token token = in_.take(what);
        at = location_of(in_.source(), token);
        return integer_from(in_.source(), token, what);
    }
    IndexTable read_vertices();
    IndexTable read_edges(const IndexTable& vertices);
    void read_polygons(const IndexTable& edges);
    void read_polygon(std::int64_t ordinal, std::int64_t count, const IndexTable& edges,
                      IndexTable& polygons);
    void warn_about_leftovers();

    WordStream in_;
    bool marks_;
    Diagnostics& diagnostics_;
    SurfaceMesh mesh_;
    std::vector<Edge> edge_list_;
};

SurfaceMesh PolygonFileReader::read() {
    const IndexTable vertices = read_vertices();
    const IndexTable edges = read_edges(vertices);
    read_polygons(edges);
    warn_about_leftovers();
    return std::move(mesh_);
}

IndexTable PolygonFileReader::read_vertices() {
    const std::int64_t vertex_count = in_.count("the vertex count", kMaxItemsPerFile);
    IndexTable vertices("vertex", reservation(vertex_count, 4));
    mesh_.vertices.reserve(reservation(vertex_count, 4));
    for (std::int64_t k = 0; k < vertex_count; ++k) {
        SourceLocation at;
        const std::int64_t index =
            take_index(fmt::format("the index number of vertex {} of {}", k + 1, vertex_count), at);
        const Vec3 p = in_.point(fmt::format("vertex {}", index));
        vertices.define(index, static_cast<std::uint32_t>(mesh_.vertices.size()), at);
        mesh_.vertices.push_back(p);
        mesh_.vertex_lines.push_back(at.line);
        trace(at.line, fmt::format("vertex {} = {}", index, show_point(p.x, p.y, p.z)));
    }
    return vertices;
}

IndexTable PolygonFileReader::read_edges(const IndexTable& vertices) {
    const std::int64_t count = in_.count("the edge count", kMaxItemsPerFile);
    IndexTable edges("edge", reservation(count, 3));
    edge_list_.reserve(reservation(count, 3));
    for (std::int64_t k = 0; k < count; ++k) {
        SourceLocation at;
        const std::int64_t index =
            take_index(fmt::format("the index number of edge {} of {}", k + 1, count), at);
        const std::string name = fmt::format("edge {}", index);
        SourceLocation a_at;
        SourceLocation b_at;
        const std::int64_t a = take_index("the first vertex of " + name, a_at);
        const std::int64_t b = take_index("the second vertex of " + name, b_at);
        edges.define(index, static_cast<std::uint32_t>(edge_list_.size()), at);
        edge_list_.push_back({vertices.find(a, a_at, name), vertices.find(b, b_at, name)});
        trace(at.line, fmt::format("edge {} = vertices {} {}", index, a, b));
    }
    return edges;
}

void PolygonFileReader::read_polygons(const IndexTable& edges) {
    const std::int64_t count = in_.count("the polygon count", kMaxItemsPerFile);
    IndexTable polygons("polygon", reservation(count, 7));
    mesh_.polygons.reserve(reservation(count, 7));
    for (std::int64_t k = 0; k < count; ++k) {
        read_polygon(k, count, edges, polygons);
    }
}

void PolygonFileReader::read_polygon(std::int64_t ordinal, std::int64_t count,
                                     const IndexTable& edges, IndexTable& polygons) {
    SourceLocation at;
    const std::int64_t index =
        take_index(fmt::format("the index number of polygon {} of {}", ordinal + 1, count), at);
    const std::string name = fmt::format("polygon {}", index);
    polygons.define(index, static_cast<std::uint32_t>(mesh_.polygons.size()), at);
    const std::int64_t n = in_.count("the edge count of " + name, kMaxEdgesPerPolygon);
    std::vector<Edge> own;
    own.reserve(static_cast<std::size_t>(std::min(n, in_.lexer().max_words_left())));
    for (std::int64_t e = 0; e < n; ++e) {
        SourceLocation e_at;
        const std::int64_t edge = take_index(fmt::format("edge {} of {}", e + 1, name), e_at);
        own.push_back(edge_list_[edges.find(edge, e_at, name)]);
    }
    MeshPolygon p;
    p.number = static_cast<long>(index);
    p.line = at.line;
    p.outward = in_.point("the outward normal of " + name);
    p.attribute_offset = static_cast<long>(in_.integer("the attribute offset of " + name));
    if (marks_) {
        const std::string mark = "the mark of " + name;
        p.mark = static_cast<PolygonMark>(integer_in(in_.source(), in_.take(mark), mark, 0, 4));
        p.shape_number = static_cast<long>(in_.integer("the shape index of " + name));
    }
    // Fewer than three edges cannot close a loop: skipped with a warning, like the polygons the
    // assembly finds degenerate, rather than stopping the whole scene.
    if (n < 3) {
        diagnostics_.warn_repeated(fmt::format("degenerate polygons in {}", at.file),
                                   fmt::format("{}: {} is degenerate (fewer than 3 edges); skipped",
                                               at.to_string(), name));
        return;
    }
    const std::vector<std::uint32_t> loop = chain_edges(own);
    if (loop.empty()) {
        throw InputError(at, "the edges of " + name + " do not form a single closed loop");
    }
    mesh_.add_polygon(p, loop);
    trace(at.line, fmt::format("{}: {} edges, outward {}, attribute offset {}, mark {}, shape {}",
                               name, n, show_point(p.outward.x, p.outward.y, p.outward.z),
                               p.attribute_offset, static_cast<int>(p.mark), p.shape_number));
}

void PolygonFileReader::warn_about_leftovers() {
    if (const auto extra = in_.lexer().peek()) {
        diagnostics_.warn(fmt::format("{}: text after the last polygon ignored, from {}",
                                      in_.source().at(extra->line).to_string(),
                                      quote_token(extra->text)));
    }
}

}  // namespace

SurfaceMesh read_polygon_file(const SourceText& source, bool marks, Diagnostics& diagnostics) {
    return PolygonFileReader(source, marks, diagnostics).read();
}

}  // namespace rt
