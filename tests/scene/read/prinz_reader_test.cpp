#include "rt/scene/read/prinz_reader.h"

#include "rt/scene/polygon_geometry.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

std::string error(const std::string& bytes) {
    Diagnostics d;
    const SourceText text = text_file("p", bytes);
    return input_error([&] { read_prinz_file(text, d); });
}

TEST(PrinzFile, TheManualsCubeIsTwelveOutwardTriangles) {
    Diagnostics d;
    const SourceText text =
        text_file("prinzcube", test::read_text(scene_data() / "manual/prinzcube"));
    const SurfaceMesh m = read_prinz_file(text, d);
    ASSERT_EQ(m.vertices.size(), 8u);
    EXPECT_EQ(m.vertices[3], (Vec3{-1, -1, 1}));  // "to find vertex 3, go down to the fourth node"
    ASSERT_EQ(m.polygons.size(), 12u);
    for (const MeshPolygon& p : m.polygons) {
        ASSERT_EQ(p.corner_count, 3u);
        const std::span<const std::uint32_t> loop(m.corners.data() + p.first_corner, 3);
        const Vec3 n = newell_normal(loop, m.vertices);
        const Vec3 centre = (m.vertices[loop[0]] + m.vertices[loop[1]] + m.vertices[loop[2]]) / 3;
        // Counter-clockwise seen from outside: the right-hand-rule normal points away from the
        // cube's centre, along one axis.
        EXPECT_GT(dot(n, centre), 0) << "face " << p.number;
        EXPECT_EQ(length(n), 4.0) << "face " << p.number;  // twice the area of half a 2x2 face
        EXPECT_EQ(p.outward, Vec3{});
    }
    EXPECT_EQ(m.polygons[0].line, 2);
    EXPECT_EQ(m.polygons[11].line, 20);
}

TEST(PrinzFile, LayoutIsFree) {
    Diagnostics d;
    const SourceText text =
        text_file("p",
                  "{solid{node{position 0 0 0}}{node{position 1 0 0}}{face{loop 0 1 2}}\r\n"
                  "{ node { position 0 1 0 } } }");
    const SurfaceMesh m = read_prinz_file(text, d);
    EXPECT_EQ(m.polygons.size(), 1u);
    EXPECT_EQ(m.vertices.size(), 3u);
}

TEST(PrinzFile, Traces) {
    RecordingDiagnostics r(true);
    const SourceText text =
        text_file("p", "{solid\n{node {position 1 1 1}}\n{face {loop 0 0 0}}\n}");
    read_prinz_file(text, r.diagnostics);
    EXPECT_EQ(r.traces,
              (std::vector<std::string>{"p:2: node 0 = (1, 1, 1)", "p:3: face 0 = nodes 0 0 0"}));
}

TEST(PrinzFile, Errors) {
    EXPECT_EQ(error(""), "p:1: expected '{' opening the solid, found end of file");
    EXPECT_EQ(error("{box}"), "p:1: expected 'solid' after the first '{', found 'box'");
    EXPECT_EQ(error("{solid\n{face {loop 0 1 2}}\n"),
              "p:2: expected '{' or the '}' closing the solid of line 1, found end of file");
    EXPECT_EQ(error("{solid {face {loop 0 1 2}}}}"),
              "p:1: expected end of file after the solid, found '}'");
    EXPECT_EQ(error("{solid\n{face {loop 0 1 2 3}}\n}"),
              "p:2: face 0 has 4 corners; filetype 2 faces must be triangles");
    EXPECT_EQ(error("{solid\n{face {loop 0 1}}\n}"),
              "p:2: face 0 has 2 corners; filetype 2 faces must be triangles");
    EXPECT_EQ(error("{solid {face {loop 0 1 2}\n{node"),
              "p:2: expected '}' closing face 0, found '{'");
    EXPECT_EQ(error("{solid {face {loop 0 1 2}\n}"),
              "p:2: expected '{' or the '}' closing the solid of line 1, found end of file");
    EXPECT_EQ(
        error("{solid {face {loop 0 x 2}}}"),
        "p:1: expected a node index or '}' in the loop of face 0 (a whole number), found 'x'");
    EXPECT_EQ(error("{solid {edge 1 2}}"), "p:1: expected 'face' or 'node', found 'edge'");
    EXPECT_EQ(error("{solid {{{{{{{{{{{{"), "p:1: expected 'face' or 'node', found '{'");
    EXPECT_EQ(error("{solid {node {position 1 2}}}"), "p:1: expected the z of node 0, found '}'");
    EXPECT_EQ(error("{solid\n{node {position 0 0 0}}\n{face {loop 0 0 3}}\n}"),
              "p:3: face 0 refers to node 3, but the file has 1 node (numbered from 0)");
    EXPECT_EQ(error("{solid {face {loop -1 0 0}}}"),
              "p:1: face 0 refers to node -1, but the file has 0 nodes (numbered from 0)");
}

}  // namespace
}  // namespace rt::test
