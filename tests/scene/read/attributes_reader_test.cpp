#include "rt/scene/read/attributes_reader.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

// The manual's three attribute lines (2.3), with its heading lines.
const std::string manual_attributes =
    "attributes\n"
    "$ 3\n"
    "color(r,g,b) lighting model(pow,tpow,e,s,d,s,t,ref) sdist tdist description\n"
    "$ 0.0 0.2 0.98 2.0 0.0 0.0 0.05 0.9 0.1 0.0 1.05 4.0 1.0 0.0 0.0 0\n"
    "$ 0.8 0.2 0.0 2.0 0.0 0.0 0.05 0.8 0.4 0.0 1.05 4.0 1.0 0.0 0.0 1\n"
    "$ 0.8 0.03 0.02 2.0 2.0 0.0 0.05 0.3 0.6 0.99 1.5 4.0 1.0 0.0 0.0 2\n";

std::vector<Attribute> read(const std::string& bytes, const ReaderDialect& dialect,
                            Diagnostics& diagnostics) {
    const SourceText text = text_file("Attributes", bytes);
    return read_attributes_file(text, dialect, diagnostics);
}

std::string error(const std::string& bytes, const ReaderDialect& dialect = {}) {
    Diagnostics d;
    return input_error([&] { read(bytes, dialect, d); });
}

TEST(AttributesFile, ReadsTheManualsThreeLines) {
    Diagnostics d;
    const std::vector<Attribute> a = read(manual_attributes, {}, d);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(a[0].color, (Rgb{0.0, 0.2, 0.98}));
    EXPECT_EQ(a[0].specular_exponent, 2.0);
    EXPECT_EQ(a[0].transmit_exponent, 0.0);
    EXPECT_EQ(a[0].emission, 0.0);
    EXPECT_EQ(a[0].ambient, 0.05);
    EXPECT_EQ(a[0].diffuse, 0.9);
    EXPECT_EQ(a[0].specular, 0.1);
    EXPECT_EQ(a[0].transmission, 0.0);
    EXPECT_EQ(a[0].refraction_index, (Rgb{1.05, 1.05, 1.05}));
    EXPECT_EQ(a[0].reflect_cone_degrees, 4.0);
    EXPECT_EQ(a[0].reflect_cone_exponent, 1.0);
    EXPECT_EQ(a[0].refract_cone_degrees, 0.0);
    EXPECT_EQ(a[0].refract_cone_exponent, 0.0);
    EXPECT_EQ(a[0].index, 0);
    EXPECT_EQ(a[0].where.to_string(), "Attributes:4");
    EXPECT_EQ(a[2].transmission, 0.99);
    EXPECT_EQ(a[2].refraction_index.g, 1.5);
    EXPECT_EQ(a[2].index, 2);
    EXPECT_TRUE(d.warnings().empty());
}

TEST(AttributesFile, DescriptionsAfterTheNumbersAreAllowed) {
    Diagnostics d;
    const auto a =
        read("$ 1 attributes\n$ 1 1 1 2 2 1 0 0 0 0 1 60 4 60 4 7 white light, 3 feet\n", {}, d);
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0].index, 7);
    EXPECT_EQ(a[0].emission, 1.0);
}

TEST(AttributesFile, WithoutPowerFieldsBothAreTwo) {
    Diagnostics d;
    ReaderDialect dp;
    dp.no_power_fields = true;
    const auto a = read("$ 1\n$ 0.5 0.5 0.5 0.1 0.2 0.3 0.4 0 1.3 60 4 50 3 9\n", dp, d);
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0].specular_exponent, 2.0);
    EXPECT_EQ(a[0].transmit_exponent, 2.0);
    EXPECT_EQ(a[0].emission, 0.1);
    EXPECT_EQ(a[0].transmission, 0.0);
    EXPECT_EQ(a[0].refraction_index, (Rgb{1.3, 1.3, 1.3}));
    EXPECT_EQ(a[0].refract_cone_exponent, 3.0);
    EXPECT_EQ(a[0].index, 9);
}

TEST(AttributesFile, WithRgbRefractionThreeIndices) {
    Diagnostics d;
    ReaderDialect r;
    r.rgb_refraction = true;
    const auto a = read("$ 1\n$ 1 1 1 2 2 0 0 0 0 1 1.50 1.52 1.54 60 4 60 4 1\n", r, d);
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0].refraction_index, (Rgb{1.50, 1.52, 1.54}));
    EXPECT_EQ(a[0].reflect_cone_degrees, 60.0);
    EXPECT_EQ(a[0].index, 1);
}

TEST(AttributesFile, IndexNumbersMayStartAnywhere) {
    Diagnostics d;
    const auto a =
        read("$ 2\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 1\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 2\n", {}, d);
    EXPECT_EQ(a[0].index, 1);
    EXPECT_EQ(a[1].index, 2);
}

TEST(AttributesFile, OddValuesAreWarnings) {
    Diagnostics d;
    read("$ 1\n$ 1.2 0 -0.1 2 2 0 -0.5 1 0 0 1 0 0 0 0 3\n", {}, d);
    EXPECT_EQ(d.warnings(),
              (std::vector<std::string>{
                  "Attributes:2: attribute 3 has a colour outside 0..1 (1.2, 0, -0.1)",
                  "Attributes:2: attribute 3 has a negative weight (e a d s t)"}));
}

TEST(AttributesFile, ExtraLinesAfterTheCountAreWarned) {
    Diagnostics d;
    read("$ 1\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 1\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 2\n", {}, d);
    EXPECT_EQ(d.warnings(), (std::vector<std::string>{
                                "Attributes:3: 1 line after the 1 attributes ignored (is the count "
                                "on the first $ line right?)"}));
}

TEST(AttributesFile, Errors) {
    const std::string line = "$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 ";
    EXPECT_EQ(error(""), "Attributes:1: expected the attribute count, found end of file");
    EXPECT_EQ(error("$ x\n"),
              "Attributes:1: expected the attribute count (a whole number), found 'x'");
    EXPECT_EQ(error("$ -2\n"),
              "Attributes:1: expected the attribute count (0 or more), found '-2'");
    EXPECT_EQ(error("$ 99999999999\n"),
              "Attributes:1: The attribute count is 99999999999, more than the limit of 50000000");
    EXPECT_EQ(error("$ 13\n" + line + "0\n" + line + "1\n" + line + "2\n"),
              "Attributes:4: expected 13 attributes, found 3");
    EXPECT_EQ(error("$ 2\n" + line + "0\n" + line + "0\n"),
              "Attributes:3: attribute 0 is defined twice (first at line 2)");
    EXPECT_EQ(error("$ 1\n$ 1 1 1 2 2 0 0 1\n"),
              "Attributes:2: expected the specular weight s, found end of line");
    EXPECT_EQ(error("$ 1\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0\n"),
              "Attributes:2: expected the attribute's index number, found end of line");
    EXPECT_EQ(
        error("$ 1\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 white\n"),
        "Attributes:2: expected the attribute's index number (a whole number), found 'white'");
    EXPECT_EQ(error("$ 1\n$ 1 nan 1 2 2 0 0 1 0 0 1 0 0 0 0 1\n"),
              "Attributes:2: expected the green intensity (-1e+06 to 1e+06), found 'nan'");
    EXPECT_EQ(error("$ 1\n$ 1 1 1 2 2 0 0 1 0 0 inf 0 0 0 0 1\n"),
              "Attributes:2: expected the index of refraction, found 'inf'");
    EXPECT_EQ(error("$ 1\n$ 1 1 1 2 2 0 0 1 0 0 0 0 0 0 0 1\n"),
              "Attributes:2: attribute 1: the index of refraction must be more than 0, found 0");
}

// Colours and weights beyond kMaxIntensity would leave the float range after a few bounces; they
// are refused at their line, the edge of the range is accepted.
TEST(AttributesFile, ColoursAndWeightsHaveALimit) {
    EXPECT_EQ(error("$ 1\n$ 1e39 1 1 2 2 0 0 1 0 0 1 0 0 0 0 1\n"),
              "Attributes:2: expected the red intensity (-1e+06 to 1e+06), found '1e39'");
    EXPECT_EQ(error("$ 1\n$ 1 1 1 2 2 2e6 0 1 0 0 1 0 0 0 0 1\n"),
              "Attributes:2: expected the emitted weight e (-1e+06 to 1e+06), found '2e6'");
    EXPECT_EQ(error("$ 1\n$ 1 1 1 2 2 0 0 1 0 -1e7 1 0 0 0 0 1\n"),
              "Attributes:2: expected the transmitted weight t (-1e+06 to 1e+06), found '-1e7'");
    Diagnostics d;
    const std::vector<Attribute> a = read("$ 1\n$ 1e6 1 1 2 2 1e6 0 1 0 0 1 0 0 0 0 1\n", {}, d);
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0].emission, 1e6);
}

TEST(AttributesFile, DialectMismatchesNameTheMissingField) {
    ReaderDialect r;
    r.rgb_refraction = true;
    // The manual's lines read with -R: two numbers short.
    EXPECT_EQ(error(manual_attributes, r),
              "Attributes:4: expected the refraction cone exponent n, found end of line");
}

// Two numbers more than the dialect's fields: the file was written for another dialect, said at
// once (with -Dp the manual's lines once read on, their indices taken from a cone exponent, and
// stopped at "attribute 0 is defined twice").
TEST(AttributesFile, TwoNumbersTooManyNameTheDialectsThatFit) {
    ReaderDialect no_power;
    no_power.no_power_fields = true;
    EXPECT_EQ(error(manual_attributes, no_power),
              "Attributes:4: expected 14 numbers, found 16: read the file without -Dp and -Of, for "
              "pow and tpow, or with -R, for three indices of refraction");
    const std::string rgb_lines = "$ 1\n$ 1 1 1 2 2 0 0 1 0 0 1.5 1.6 1.7 0 0 0 0 5\n";
    EXPECT_EQ(error(rgb_lines, {}),
              "Attributes:2: expected 16 numbers, found 18: read the file with -R, for three "
              "indices of refraction");
    // With -R and pow and tpow no dialect has more fields: two more numbers are a description.
    ReaderDialect rgb;
    rgb.rgb_refraction = true;
    Diagnostics d;
    const std::string long_lines = "$ 1\n$ 1 1 1 2 2 0 0 1 0 0 1.5 1.6 1.7 0 0 0 0 5 6 7\n";
    EXPECT_EQ(read(long_lines, rgb, d).at(0).index, 5);
}

TEST(InlineAttributes, ReadFromTheScnStream) {
    const SourceText text =
        text_file("s.scn",
                  "attributes follow\n$ 2 attributes\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 5 first\n"
                  "comment\n$ 1 0 0 2 2 0 0 1 0 0 1 0 0 0 0 6\n$ 3\n");
    ItemStream scn(text);
    Diagnostics d;
    const auto a = read_inline_attributes(scn, {}, d);
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[1].index, 6);
    EXPECT_EQ(a[1].where.to_string(), "s.scn:5");
    EXPECT_EQ(scn.integer("the entity count"), 3);
}

TEST(InlineAttributes, TooFewLines) {
    const SourceText text = text_file("s.scn", "$ 2\n$ 1 1 1 2 2 0 0 1 0 0 1 0 0 0 0 5\n");
    ItemStream scn(text);
    Diagnostics d;
    EXPECT_EQ(input_error([&] { read_inline_attributes(scn, {}, d); }),
              "s.scn:2: expected 2 attributes, found 1");
}

}  // namespace
}  // namespace rt::test
