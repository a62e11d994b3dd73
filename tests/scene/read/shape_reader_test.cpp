#include "rt/scene/read/shape_reader.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

std::string error(const std::string& bytes) {
    Diagnostics d;
    const SourceText text = text_file("shapes", bytes);
    return input_error([&] { read_shape_file(text, d); });
}

TEST(ShapeFile, ShapesAreNumberedByOrderFromZero) {
    Diagnostics d;
    const SourceText text = text_file(
        "shapes", "shapes\n$ 2\nsphere\n$ 0 0 0 1.5 0 0 0 ball\n$ 1 2 3 30 1 5 3 a cone\n");
    const std::vector<Shape> s = read_shape_file(text, d);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].index, 0);
    EXPECT_EQ(s[0].radius_or_angle, 1.5);
    EXPECT_EQ(s[0].where.to_string(), "shapes:4");
    EXPECT_EQ(s[1].index, 1);
    EXPECT_EQ(s[1].first, (Vec3{1, 2, 3}));
    EXPECT_EQ(s[1].radius_or_angle, 30.0);
    EXPECT_EQ(s[1].second, (Vec3{1, 5, 3}));
}

TEST(ShapeFile, Errors) {
    EXPECT_EQ(error(""), "shapes:1: expected the shape count, found end of file");
    EXPECT_EQ(error("$ 2\n$ 0 0 0 1 0 0 0\n"), "shapes:2: expected 2 shapes, found 1");
    EXPECT_EQ(error("$ 1\n$ 0 0 0 1 0 0\n"),
              "shapes:2: expected the shape's second z, found end of line");
    EXPECT_EQ(error("$ 1\n$ 0 0 0 inf 0 0 0\n"),
              "shapes:2: expected the shape's radius or cone half-angle, found 'inf'");
    EXPECT_EQ(error("$ -1\n"), "shapes:1: expected the shape count (0 or more), found '-1'");
}

}  // namespace
}  // namespace rt::test
