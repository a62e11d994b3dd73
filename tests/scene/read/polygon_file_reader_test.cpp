#include "rt/scene/read/polygon_file_reader.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

SurfaceMesh read(const std::string& bytes, bool marks, Diagnostics& d) {
    const SourceText text = text_file("sq", bytes);
    return read_polygon_file(text, marks, d);
}

std::string error(const std::string& bytes, bool marks = false) {
    Diagnostics d;
    return input_error([&] { read(bytes, marks, d); });
}

std::vector<std::uint32_t> corners(const SurfaceMesh& m, std::size_t polygon) {
    const MeshPolygon& p = m.polygons.at(polygon);
    return {m.corners.begin() + p.first_corner,
            m.corners.begin() + p.first_corner + p.corner_count};
}

// The manual's square (2.5), one number or one item per line as it prints them.
const std::string manual_square =
    "4\n0 -1 0 -1\n1 1 0 -1\n2 1 0 1\n3 -1 0 1\n4\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n1\n"
    "0 4 0 1 2 3 0 -1 0 0\n";

TEST(PolygonFile, ReadsTheManualsSquare) {
    Diagnostics d;
    const SurfaceMesh m = read(manual_square, false, d);
    ASSERT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.vertices[2], (Vec3{1, 0, 1}));
    ASSERT_EQ(m.polygons.size(), 1u);
    EXPECT_EQ(corners(m, 0), (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(m.polygons[0].outward, (Vec3{0, -1, 0}));
    EXPECT_EQ(m.polygons[0].attribute_offset, 0);
    EXPECT_EQ(m.polygons[0].line, 12);
    EXPECT_EQ(m.polygons[0].mark, PolygonMark::Ordinary);
    EXPECT_TRUE(d.warnings().empty());
}

TEST(PolygonFile, LineBreaksCarryNoMeaning) {
    Diagnostics d;
    const SurfaceMesh m = read(
        "4 0 -1 0 -1 1 1 0 -1 2 1 0 1 3 -1 0 1 4 0 0 1 1 1 2 2 2 3 3 3 0\r\n"
        "1 0 4 0 1 2 3\n0 -1 0\n0",
        false, d);
    EXPECT_EQ(m.polygons.size(), 1u);
    EXPECT_EQ(m.polygons[0].line, 2);
}

TEST(PolygonFile, IndexNumbersAreMatchedByValue) {
    Diagnostics d;
    // Counting from 1, edges in reverse orientation and out of order.
    const SurfaceMesh m = read(
        "3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n3\n10 2 1\n30 1 3\n20 3 2\n1\n"
        "7 3 10 30 20 0 0 1 2\n",
        false, d);
    EXPECT_EQ(m.polygons[0].number, 7);
    EXPECT_EQ(m.polygons[0].attribute_offset, 2);
    EXPECT_EQ(corners(m, 0), (std::vector<std::uint32_t>{1, 0, 2}));
}

TEST(PolygonFile, MarksAndShapeIndicesWithM) {
    Diagnostics d;
    const SurfaceMesh m = read(
        "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 2 0 3 0 1 2 0 0 1 "
        "0 2 5 1 3 0 1 2 0 0 1 0 1 -1",
        true, d);
    ASSERT_EQ(m.polygons.size(), 2u);
    EXPECT_EQ(m.polygons[0].mark, PolygonMark::Sphere);
    EXPECT_EQ(m.polygons[0].shape_number, 5);
    EXPECT_EQ(m.polygons[1].mark, PolygonMark::InterpolatesNormals);
}

TEST(PolygonFile, FewerThanThreeEdgesIsDegenerate) {
    Diagnostics d;
    const SurfaceMesh m =
        read("2 0 0 0 0 1 1 0 0 1 0 0 1 2\n0 2 0 0 0 0 1 0\n1 0 0 0 1 0", false, d);
    EXPECT_TRUE(m.polygons.empty());
    EXPECT_EQ(d.warnings(), (std::vector<std::string>{
                                "sq:2: polygon 0 is degenerate (fewer than 3 edges); skipped",
                                "sq:3: polygon 1 is degenerate (fewer than 3 edges); skipped"}));
}

TEST(PolygonFile, TextAfterTheLastPolygonIsWarned) {
    Diagnostics d;
    read(manual_square + "junk 1 2\n", false, d);
    EXPECT_EQ(
        d.warnings(),
        (std::vector<std::string>{"sq:13: text after the last polygon ignored, from 'junk'"}));
}

TEST(PolygonFile, TracesEachItem) {
    RecordingDiagnostics r(true);
    read(manual_square, false, r.diagnostics);
    ASSERT_EQ(r.traces.size(), 9u);
    EXPECT_EQ(r.traces[0], "sq:2: vertex 0 = (-1, 0, -1)");
    EXPECT_EQ(r.traces[4], "sq:7: edge 0 = vertices 0 1");
    EXPECT_EQ(r.traces[8],
              "sq:12: polygon 0: 4 edges, outward (0, -1, 0), attribute offset 0, "
              "mark 0, shape -1");
}

TEST(PolygonFile, Errors) {
    EXPECT_EQ(error(""), "sq:1: expected the vertex count, found end of file");
    EXPECT_EQ(error("-4"), "sq:1: expected the vertex count (0 or more), found '-4'");
    EXPECT_EQ(error("4.5"), "sq:1: expected the vertex count (a whole number), found '4.5'");
    EXPECT_EQ(error("60000000"),
              "sq:1: The vertex count is 60000000, more than the limit of 50000000");
    // A huge count that fits the limit but not the file: no huge allocation, just the end.
    EXPECT_EQ(error("40000000\n0 1 2 3\n"),
              "sq:2: expected the index number of vertex 2 of 40000000, found end of file");
    EXPECT_EQ(error("4\n0 -1 0 -1\n1 1 0"), "sq:3: expected the z of vertex 1, found end of file");
    EXPECT_EQ(error("2\n0 0 0 NaN\n"), "sq:2: expected the z of vertex 0, found 'NaN'");
    EXPECT_EQ(error("2\n0 0 0 0\n0 1e999 0 0\n"),
              "sq:3: expected the x of vertex 0, found '1e999'");
    EXPECT_EQ(error("2\n0 0 0 0\n0 1 0 0\n"), "sq:3: vertex 0 is defined twice (first at line 2)");
    EXPECT_EQ(error("2\n0 0 0 0\n1 1 0 0\n1\n0 0\n9\n"),
              "sq:6: edge 0 refers to vertex 9, which is not defined");
    EXPECT_EQ(error("2\n0 0 0 0\n1 1 0 0\n2\n0 0 1\n0 1 0\n"),
              "sq:6: edge 0 is defined twice (first at line 5)");
    const std::string square_edges =
        "4\n0 -1 0 -1\n1 1 0 -1\n2 1 0 1\n3 -1 0 1\n4\n0 0 1\n"
        "1 1 2\n2 2 3\n3 3 0\n";
    EXPECT_EQ(error(square_edges + "1\n0 4 0 1 2\n7 0 -1 0 0\n"),
              "sq:13: polygon 0 refers to edge 7, which is not defined");
    EXPECT_EQ(error(square_edges + "1\n0 4 0 1 2 3 0 -1\n"),
              "sq:12: expected the z of the outward normal of polygon 0, found end of file");
    EXPECT_EQ(error(square_edges + "1\n0 4 0 1 2 3 0 -1 0 x\n"),
              "sq:12: expected the attribute offset of polygon 0 (a whole number), found 'x'");
    EXPECT_EQ(error(square_edges + "1\n0 200000 0\n"),
              "sq:12: The edge count of polygon 0 is 200000, more than the limit of 100000");
    EXPECT_EQ(error(square_edges + "1\n0 -1\n"),
              "sq:12: expected the edge count of polygon 0 (0 or more), found '-1'");
    EXPECT_EQ(error(square_edges + "1\n0 3 0 1 2 0 -1 0 0\n"),
              "sq:12: the edges of polygon 0 do not form a single closed loop");
    EXPECT_EQ(error(square_edges + "2\n0 4 0 1 2 3 0 -1 0 0\n0 4 0 1 2 3 0 -1 0 0\n"),
              "sq:13: polygon 0 is defined twice (first at line 12)");
    EXPECT_EQ(error(square_edges + "1\n0 4 0 1 2 3 0 -1 0 0 7 0\n", true),
              "sq:12: expected the mark of polygon 0 (0 to 4), found '7'");
    EXPECT_EQ(error(square_edges + "1\n0 4 0 1 2 3 0 -1 0 0 2\n", true),
              "sq:12: expected the shape index of polygon 0, found end of file");
}

}  // namespace
}  // namespace rt::test
