// What the readers tell besides the geometry: the -df parse trace of shape and Phigs+ files, one
// line per item with its numbers, and the warning for lines after the last shape.
#include "rt/scene/read/phigs_reader.h"
#include "rt/scene/read/shape_reader.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

TEST(ReaderTraces, ShapeFileTracesEveryShapeWithItsNumbers) {
    RecordingDiagnostics d(true);
    const SourceText text =
        text_file("shapes", "shapes\n$ 2\n$ 0 0 0 1.5 0 0 0 ball\n$ 1 2 3 30 1 5 3 a cone\n");
    read_shape_file(text, d.diagnostics);
    EXPECT_EQ(d.traces, (std::vector<std::string>{"shapes:3: shape 0: (0, 0, 0) 1.5 (0, 0, 0)",
                                                  "shapes:4: shape 1: (1, 2, 3) 30 (1, 5, 3)"}));
    EXPECT_TRUE(d.diagnostics.warnings().empty());
}

TEST(ReaderTraces, LinesAfterTheLastShapeAreIgnoredWithAWarning) {
    Diagnostics d;
    const SourceText text =
        text_file("shapes", "$ 1\n$ 0 0 0 1 0 0 0\ncomment lines are not $ lines\n$ 9 9 9 9\n");
    const std::vector<Shape> shapes = read_shape_file(text, d);
    EXPECT_EQ(shapes.size(), 1U);
    EXPECT_EQ(d.warnings(),
              std::vector<std::string>{"shapes:4: 1 line after the 1 shapes ignored (is the count "
                                       "on the first $ line right?)"});
}

TEST(ReaderTraces, PhigsFileTracesEveryFillArea) {
    RecordingDiagnostics d(true);
    const SourceText text =
        text_file("f.phigs",
                  "FILL_AREA_SET_3_WITH_DATA\n"
                  "  FACET_NORMAL 0 0 -1\n"
                  "  ATTRIBUTE_OFFSET 2\n"
                  "  BOUNDARY 4 -1 -1 0  -1 1 0  1 1 0  1 -1 0\n"
                  "END\n"
                  "FILL_AREA_SET_3_WITH_DATA BOUNDARY 3 0 0 1 1 0 1 0 1 1 END\n");
    const SurfaceMesh mesh = read_phigs_file(text, d.diagnostics);
    EXPECT_EQ(mesh.polygons.size(), 2U);
    EXPECT_EQ(
        d.traces,
        (std::vector<std::string>{
            "f.phigs:1: fill area 0: 4 corners, facet normal (0, 0, -1), attribute offset 2",
            "f.phigs:6: fill area 1: 3 corners, facet normal (0, 0, 0), attribute offset 0"}));
}

}  // namespace
}  // namespace rt::test
