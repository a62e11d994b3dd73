#include "rt/core/text.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(ParseDouble, AcceptsTheUsualSpellings) {
    EXPECT_EQ(parse_double("2"), 2.0);
    EXPECT_EQ(parse_double("-1.5"), -1.5);
    EXPECT_EQ(parse_double(".5"), 0.5);
    EXPECT_EQ(parse_double("+3e2"), 300.0);
    EXPECT_EQ(parse_double("1."), 1.0);
}

TEST(ParseDouble, RejectsJunkNanAndInfinity) {
    EXPECT_FALSE(parse_double(""));
    EXPECT_FALSE(parse_double("x"));
    EXPECT_FALSE(parse_double("1.0x"));
    EXPECT_FALSE(parse_double("nan"));
    EXPECT_FALSE(parse_double("inf"));
    EXPECT_FALSE(parse_double("1e400"));
    EXPECT_FALSE(parse_double("+-1"));
}

TEST(ParseInteger, AcceptsWholeNumbersWrittenAsReals) {
    EXPECT_EQ(parse_integer("12"), 12);
    EXPECT_EQ(parse_integer("-3"), -3);
    EXPECT_EQ(parse_integer("+4"), 4);
    EXPECT_EQ(parse_integer("4.0"), 4);
    EXPECT_FALSE(parse_integer("4.5"));
    EXPECT_FALSE(parse_integer("four"));
    EXPECT_FALSE(parse_integer(""));
}

TEST(Cat, JoinsThePiecesInOrder) {
    const std::string middle = "b";
    EXPECT_EQ(cat({"a", middle, "", "cd"}), "abcd");
    EXPECT_EQ(cat({}), "");
}

}  // namespace
}  // namespace rt
