#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <string>
#include <thread>

#include "rt/scene/read/dollar_lines.h"
#include "rt/scene/read/item_stream.h"
#include "rt/scene/read/word_lexer.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rt::test {
namespace {

std::vector<std::string> dollar_words(const SourceText& text) {
    std::vector<std::string> out;
    DollarLineReader reader(text);
    DollarLine line;
    while (reader.next(line)) {
        std::string words = std::to_string(line.line) + ":";
        for (const Token& t : line.tokens) {
            // Appended piece by piece: `" " + std::string(...)` trips a GCC 12 -Wrestrict
            // false alarm.
            words.append(" ").append(t.text).append("@").append(std::to_string(t.column));
        }
        out.push_back(words);
    }
    return out;
}

TEST(DollarLines, KeepsOnlyLinesWhoseFirstNonBlankIsADollar) {
    const SourceText text =
        text_file("f", "heading\n$ 1 2\n  \t$3 x\nnot $ this\n$\n\t $ @shapes\n");
    EXPECT_EQ(dollar_words(text),
              (std::vector<std::string>{"2: 1@3 2@5", "3: 3@5 x@7", "6: @shapes@5"}));
}

TEST(DollarLines, HandlesCrlfTabsAndAMissingFinalNewline) {
    const SourceText text = text_file("f", "a\r\n$\t1\t 2\r\n$ 3");
    EXPECT_EQ(dollar_words(text), (std::vector<std::string>{"2: 1@3 2@6", "3: 3@3"}));
}

TEST(DollarLines, EmptyFileHasNoLines) {
    EXPECT_TRUE(dollar_words(text_file("f", "")).empty());
    EXPECT_EQ(text_file("f", "").last_line(), 1);
    EXPECT_EQ(text_file("f", "a\nb\n").last_line(), 2);
    EXPECT_EQ(text_file("f", "a\nb").last_line(), 2);
}

TEST(WordLexer, FreeFormNumbersIgnoreLineBreaks) {
    const SourceText text = text_file("f", "4\r\n 0 -1\t0\n\n   -1");
    WordLexer lexer(text);
    std::vector<std::string> words;
    while (auto t = lexer.next()) {
        words.push_back(std::string(t->text) + "@" + std::to_string(t->line) + ":" +
                        std::to_string(t->column));
    }
    EXPECT_EQ(words, (std::vector<std::string>{"4@1:1", "0@2:2", "-1@2:4", "0@2:7", "-1@4:4"}));
}

TEST(WordLexer, BracesAreWordsOfTheirOwn) {
    const SourceText text = text_file("f", "{solid{face {loop 1 2 3}}}");
    WordLexer lexer(text, WordLexerOptions{.braces = true});
    std::string joined;
    while (auto t = lexer.next()) {
        joined += std::string(t->text) + "|";
    }
    EXPECT_EQ(joined, "{|solid|{|face|{|loop|1|2|3|}|}|}|");
}

TEST(WordLexer, HashCommentsRunToTheEndOfTheLine) {
    const SourceText text = text_file("f", "A # b c\n#d\nE#f\n");
    WordLexer lexer(text, WordLexerOptions{.hash_comments = true});
    std::string joined;
    while (auto t = lexer.next()) {
        joined += std::string(t->text) + "@" + std::to_string(t->line) + "|";
    }
    EXPECT_EQ(joined, "A@1|E@3|");
}

TEST(WordLexer, BoundsTheWordsLeft) {
    const SourceText text = text_file("f", "1 2 3 4");
    WordLexer lexer(text);
    EXPECT_GE(lexer.max_words_left(), 4);
    EXPECT_LE(lexer.max_words_left(), 5);
}

TEST(ItemStream, ItemsCrossLinesAndWordsAfterAnItemAreAComment) {
    const SourceText text = text_file("s.scn", "$ 1 2\n$ 3 optical surface\n$ 4 5\n$ 6 @x\n");
    ItemStream scn(text);
    EXPECT_EQ(scn.integer("a"), 1);
    EXPECT_EQ(scn.integer("b"), 2);
    EXPECT_EQ(scn.integer("c"), 3);
    scn.end_item();  // skips "optical surface"
    EXPECT_EQ(scn.integer("d"), 4);
    scn.end_item();  // "5" is a number: the next item
    EXPECT_EQ(scn.integer("e"), 5);
    EXPECT_EQ(scn.integer("f"), 6);
    scn.end_item();  // "@x" is kept
    EXPECT_EQ(scn.take("g").text, "@x");
    EXPECT_EQ(scn.peek(), nullptr);
    EXPECT_EQ(input_error([&] { scn.take("the entity count"); }),
              "s.scn:4: expected the entity count, found end of file");
}

TEST(ItemStream, ReportsTheLineOfTheOffendingToken) {
    const SourceText text = text_file("s.scn", "$ 1\nx\n$ 2 y\n");
    ItemStream scn(text);
    scn.number("a");
    scn.number("b");
    EXPECT_EQ(input_error([&] { scn.number("c"); }), "s.scn:3: expected c, found 'y'");
}

TEST(SourceText, RefusesNulAndControlBytes) {
    TempDir dir;
    const auto nul = dir.write("nul.scn", std::string("$ 1\n$ 2\0 3\n", 11));
    EXPECT_EQ(input_error([&] { read_scene_file(nul); }),
              nul.string() + ":2: unexpected NUL byte; this is not a text file");
    const auto bell = dir.write("bell.scn", "$ 1\x07\n");
    EXPECT_EQ(input_error([&] { read_scene_file(bell); }),
              bell.string() + ":1: unexpected control character 0x07; this is not a text file");
}

// A binary file is refused at its first bad block, not read whole first (a 300 MB file of zeros
// took half a gigabyte): a pipe that sends NULs and stays open must not block the reader.
TEST(SourceText, StopsReadingAtTheFirstBinaryBlock) {
    TempDir dir;
    const std::filesystem::path pipe = dir.path() / "zeros.scn";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    std::promise<void> read_done;
    std::atomic<bool> closed{false};
    std::thread writer([&, done = read_done.get_future()] {
        const int fd = ::open(pipe.c_str(), O_WRONLY);
        const std::string zeros(1 << 16, '\0');
        [[maybe_unused]] const ssize_t n = ::write(fd, zeros.data(), zeros.size());
        done.wait_for(std::chrono::seconds(30));  // open until the reader is done, or gives up
        closed = true;
        ::close(fd);
    });
    EXPECT_EQ(input_error([&] { read_scene_file(pipe); }),
              pipe.string() + ":1: unexpected NUL byte; this is not a text file");
    EXPECT_FALSE(closed) << "the reader waited for the end of the file";
    read_done.set_value();
    writer.join();
}

// Lone CRs (the classic Mac OS's line ends) end lines as LF does; CRLF stays as it is.
TEST(SourceText, ReadsLoneCarriageReturnsAsLineEnds) {
    TempDir dir;
    const auto mac = dir.write("mac.scn", "heading\r$ 1 2\r$ 3\r\n$ 4\r");
    const SourceText text = read_scene_file(mac);
    EXPECT_EQ(text.bytes, "heading\n$ 1 2\n$ 3\r\n$ 4\n");
    EXPECT_EQ(dollar_words(text), (std::vector<std::string>{"2: 1@3 2@5", "3: 3@3", "4: 4@3"}));
    const auto bad = dir.write("bad.scn", std::string("$ 1\r$ 2\0\r", 9));
    EXPECT_EQ(input_error([&] { read_scene_file(bad); }),
              bad.string() + ":2: unexpected NUL byte; this is not a text file");
}

TEST(SourceText, DropsAFinalCtrlZ) {
    TempDir dir;
    const auto file = dir.write("dos.scn", "$ 1\r\n\x1a");
    EXPECT_EQ(read_scene_file(file).bytes, "$ 1\r\n");
}

TEST(SourceText, MissingDirectoryAndHugeFilesAreInputErrors) {
    TempDir dir;
    EXPECT_EQ(input_error([&] { read_scene_file(dir.path() / "none.scn"); }),
              (dir.path() / "none.scn").string() +
                  ": cannot open the scene file: No such file or directory");
    EXPECT_EQ(input_error([&] { read_scene_file(dir.path()); }),
              dir.path().string() + ": cannot open the scene file: Is a directory");
    const auto big = dir.write("big", "");
    std::filesystem::resize_file(big, (std::uintmax_t{1} << 30) + 1);  // sparse: no disk used
    EXPECT_EQ(input_error([&] {
                  read_named_file(big, "optical surface file", "big", {"a.scn", 7, 3});
              }),
              "a.scn:7: cannot open optical surface file 'big' (" + big.string() +
                  "): larger than the 1 GiB limit for input files");
}

}  // namespace
}  // namespace rt::test
