#include "rt/scene/read/phigs_reader.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

std::string error(const std::string& bytes) {
    Diagnostics d;
    const SourceText text = text_file("ph", bytes);
    return input_error([&] { read_phigs_file(text, d); });
}

TEST(PhigsFile, ReadsTheShippedCube) {
    Diagnostics d;
    const SourceText text = text_file("phigscube", read_text(scene_data() / "phigscube"));
    const SurfaceMesh m = read_phigs_file(text, d);
    ASSERT_EQ(m.polygons.size(), 6u);
    EXPECT_EQ(m.vertices.size(), 24u);
    EXPECT_EQ(m.polygons[0].outward, (Vec3{0, 0, -1}));
    EXPECT_EQ(m.polygons[2].attribute_offset, 1);
    EXPECT_EQ(m.polygons[5].outward, Vec3{});
    EXPECT_EQ(m.polygons[1].line, 8);
    EXPECT_EQ(m.polygons[5].corner_count, 4u);
}

TEST(PhigsFile, EmptyFileHasNoPolygons) {
    Diagnostics d;
    const SourceText text = text_file("ph", "# nothing here\n");
    EXPECT_TRUE(read_phigs_file(text, d).polygons.empty());
}

TEST(PhigsFile, Errors) {
    EXPECT_EQ(error("POLYLINE_3 2 0 0 0 1 1 1"),
              "ph:1: expected FILL_AREA_SET_3_WITH_DATA, found 'POLYLINE_3'");
    EXPECT_EQ(error("FILL_AREA_SET_3_WITH_DATA\nBOUNDARY 3 0 0 0 1 0 0 0 1 0\n"),
              "ph:2: expected FACET_NORMAL, ATTRIBUTE_OFFSET, BOUNDARY or END in fill area 0, "
              "found end of file");
    EXPECT_EQ(error("FILL_AREA_SET_3_WITH_DATA FACET_NORMAL 0 0 1 END"),
              "ph:1: fill area 0 has no BOUNDARY");
    EXPECT_EQ(error("FILL_AREA_SET_3_WITH_DATA\nBOUNDARY 3 0 0 0 1 0 0 0 1 0\n"
                    "BOUNDARY 3 0 0 0 1 0 0 0 1 0 END"),
              "ph:3: fill area 0 has a second BOUNDARY: holes are not supported; write one "
              "record per polygon");
    EXPECT_EQ(error("FILL_AREA_SET_3_WITH_DATA FACET_NORMAL 0 0 1 FACET_NORMAL 0 0 1"),
              "ph:1: fill area 0 has a second FACET_NORMAL");
    EXPECT_EQ(error("FILL_AREA_SET_3_WITH_DATA BOUNDARY 3 0 0 0 1 0 0 0 1 END"),
              "ph:1: expected the z of corner 3 of fill area 0, found 'END'");
    EXPECT_EQ(error("FILL_AREA_SET_3_WITH_DATA BOUNDARY -3"),
              "ph:1: expected the corner count of fill area 0 (0 or more), found '-3'");
    EXPECT_EQ(error("FILL_AREA_SET_3_WITH_DATA COLOUR 1 0 0"),
              "ph:1: expected FACET_NORMAL, ATTRIBUTE_OFFSET, BOUNDARY or END in fill area 0, "
              "found 'COLOUR'");
}

}  // namespace
}  // namespace rt::test
