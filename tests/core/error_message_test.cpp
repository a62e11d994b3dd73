// The shapes of the library's error messages: "file:line: message", "expected X, found Y", quoted
// tokens cut short, and every kind of error catchable as rt::Error.
#include <string>

#include "rt/core/error.h"
#include "rt/core/text.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(SourceLocation, IsFileColonLineOrJustTheFile) {
    EXPECT_EQ((SourceLocation{"scenes/a.scn", 12, 3}).to_string(), "scenes/a.scn:12");
    EXPECT_EQ((SourceLocation{"scenes/a.scn", 0, 0}).to_string(), "scenes/a.scn");
}

TEST(InputError, PrefixesTheLocationAndKeepsItsParts) {
    const InputError e({"cube", 7, 2}, "polygon 3 has 2 corners");
    EXPECT_EQ(std::string(e.what()), "cube:7: polygon 3 has 2 corners");
    EXPECT_EQ(e.where().file, "cube");
    EXPECT_EQ(e.where().line, 7);
    EXPECT_EQ(e.where().column, 2);
    EXPECT_EQ(e.message(), "polygon 3 has 2 corners");
}

TEST(InputError, ExpectedFoundReadsAsOneSentence) {
    const InputError e = expected_found({"a.scn", 4, 0}, "a number", quote_token("x"));
    EXPECT_EQ(std::string(e.what()), "a.scn:4: expected a number, found 'x'");
}

TEST(Errors, EveryKindIsAnRtError) {
    const auto kind_of = [](auto thrown) -> std::string {
        try {
            throw thrown;
        } catch (const Error& e) {
            return e.what();
        }
    };
    EXPECT_EQ(kind_of(UsageError("bad switch")), "bad switch");
    EXPECT_EQ(kind_of(NotImplementedError("-w")), "-w");
    EXPECT_EQ(kind_of(IoError("disk full")), "disk full");
    EXPECT_EQ(kind_of(InputError({"f", 1, 0}, "m")), "f:1: m");
}

TEST(QuoteToken, QuotesShortTokensWhole) {
    EXPECT_EQ(quote_token(""), "''");
    EXPECT_EQ(quote_token("abc"), "'abc'");
    EXPECT_EQ(quote_token(std::string(40, 'x')), "'" + std::string(40, 'x') + "'");
}

TEST(QuoteToken, CutsLongTokensAfterFortyCharacters) {
    EXPECT_EQ(quote_token(std::string(41, 'y')), "'" + std::string(40, 'y') + "...'");
    EXPECT_EQ(quote_token(std::string(5000, 'z')), "'" + std::string(40, 'z') + "...'");
}

}  // namespace
}  // namespace rt
