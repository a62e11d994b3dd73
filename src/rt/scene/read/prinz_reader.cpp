#include "rt/scene/read/prinz_reader.h"

#include <array>

#include "rt/scene/read/reader_limits.h"
#include "rt/scene/read/word_stream.h"

#include <fmt/format.h>

namespace rt {

namespace {

struct Face {
    std::array<std::int64_t, 3> nodes{};
    int line = 0;
};

// The grammar is fixed, so braces can nest at most three deep: anything deeper is a word where
// the grammar expects another, and is refused at once.
class PrinzReader {
public:
    PrinzReader(const SourceText& source, Diagnostics& diagnostics)
        : in_(source, WordLexerOptions{.braces = true}), diagnostics_(diagnostics) {}

    SurfaceMesh read();

private:
    void read_face(int line);
    void read_node(int line);
    void trace(int line, const std::string& text) {
        if (diagnostics_.tracing()) {
            diagnostics_.trace(in_.source().at(line).to_string() + ": " + text);
        }
    }
    void check_room() {
        if (std::ssize(faces_) + std::ssize(mesh_.vertices) >= kMaxItemsPerFile) {
            throw InputError(in_.source().at(in_.lexer().line()),
                             fmt::format("more than {} faces and nodes", kMaxItemsPerFile));
        }
    }

    WordStream in_;
    Diagnostics& diagnostics_;
    SurfaceMesh mesh_;
    std::vector<Face> faces_;
};

SurfaceMesh PrinzReader::read() {
    const Token open = in_.expect("{", "'{' opening the solid");
    in_.expect("solid", "'solid' after the first '{'");
    const std::string close =
        fmt::format("'{{' or the '}}' closing the solid of line {}", open.line);
    for (Token t = in_.take(close); t.text != "}"; t = in_.take(close)) {
        if (t.text != "{") {
            throw expected_found(location_of(in_.source(), t), close, quote_token(t.text));
        }
        const Token kind = in_.take("'face' or 'node'");
        check_room();
        if (kind.text == "face") {
            read_face(kind.line);
        } else if (kind.text == "node") {
            read_node(kind.line);
        } else {
            throw expected_found(location_of(in_.source(), kind), "'face' or 'node'",
                                 quote_token(kind.text));
        }
    }
    if (const auto extra = in_.lexer().peek()) {
        throw expected_found(location_of(in_.source(), *extra), "end of file after the solid",
                             quote_token(extra->text));
    }
    const auto node_count = static_cast<std::int64_t>(mesh_.vertices.size());
    for (std::size_t k = 0; k < faces_.size(); ++k) {
        std::vector<std::uint32_t> loop;
        for (const std::int64_t node : faces_[k].nodes) {
            if (node < 0 || node >= node_count) {
                throw InputError(in_.source().at(faces_[k].line),
                                 fmt::format("face {} refers to node {}, but the file has {} "
                                             "(numbered from 0)",
                                             k, node, count_of(node_count, "node")));
            }
            loop.push_back(static_cast<std::uint32_t>(node));
        }
        MeshPolygon p;
        p.number = static_cast<long>(k);
        p.line = faces_[k].line;
        mesh_.add_polygon(p, loop);
    }
    return std::move(mesh_);
}

void PrinzReader::read_face(int line) {
    const std::string name = fmt::format("face {}", faces_.size());
    in_.expect("{", "'{' before the loop of " + name);
    in_.expect("loop", "'loop' in " + name);
    Face face;
    face.line = line;
    int corners = 0;
    const std::string what = "a node index or '}' in the loop of " + name;
    for (Token t = in_.take(what); t.text != "}"; t = in_.take(what)) {
        const std::int64_t node = integer_from(in_.source(), t, what);
        if (corners < 3) {
            face.nodes[static_cast<std::size_t>(corners)] = node;
        }
        if (++corners > kMaxEdgesPerPolygon) {
            break;  // reported as not a triangle below
        }
    }
    if (corners != 3) {
        throw InputError(
            in_.source().at(line),
            fmt::format("{} has {} corners; filetype 2 faces must be triangles", name, corners));
    }
    in_.expect("}", "'}' closing " + name);
    faces_.push_back(face);
    trace(line,
          fmt::format("{} = nodes {} {} {}", name, face.nodes[0], face.nodes[1], face.nodes[2]));
}

void PrinzReader::read_node(int line) {
    const std::string name = fmt::format("node {}", mesh_.vertices.size());
    in_.expect("{", "'{' before the position of " + name);
    in_.expect("position", "'position' in " + name);
    const Vec3 p = in_.point(name);
    in_.expect("}", "'}' after the position of " + name);
    in_.expect("}", "'}' closing " + name);
    mesh_.vertices.push_back(p);
    mesh_.vertex_lines.push_back(line);
    trace(line, fmt::format("{} = {}", name, show_point(p.x, p.y, p.z)));
}

}  // namespace

SurfaceMesh read_prinz_file(const SourceText& source, Diagnostics& diagnostics) {
    return PrinzReader(source, diagnostics).read();
}

}  // namespace rt
