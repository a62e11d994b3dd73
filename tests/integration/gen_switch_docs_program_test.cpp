// gen_switch_docs as the README runs it: to a file, to standard output, and its help.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

TEST(GenSwitchDocsProgram, WritesTheSameTextToAFileOrToStandardOutput) {
    const TempDir dir;
    const ProgramResult to_stdout = run_program("gen_switch_docs", {}, dir.path());
    ASSERT_EQ(to_stdout.exit_code, 0) << to_stdout.err;
    EXPECT_TRUE(to_stdout.out.starts_with("# Command-line switches\n")) << to_stdout.out;
    const ProgramResult to_file = run_program("gen_switch_docs", {"switches.md"}, dir.path());
    ASSERT_EQ(to_file.exit_code, 0) << to_file.err;
    EXPECT_EQ(to_file.out, "");
    EXPECT_EQ(read_text(dir.path() / "switches.md"), to_stdout.out);
}

TEST(GenSwitchDocsProgram, HelpIsNotAFileName) {
    const TempDir dir;
    const ProgramResult help = run_program("gen_switch_docs", {"--help"}, dir.path());
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("Usage: gen_switch_docs [OPTIONS] [PATH]\n"), std::string::npos)
        << help.out;
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(GenSwitchDocsProgram, RefusesASecondPathOrAnUnknownOption) {
    const TempDir dir;
    const std::string pointer = "gen_switch_docs: run 'gen_switch_docs --help' for the options\n";
    const ProgramResult two = run_program("gen_switch_docs", {"a.md", "b.md"}, dir.path());
    EXPECT_EQ(two.exit_code, 2);
    EXPECT_EQ(two.err,
              "gen_switch_docs: The following argument was not expected: b.md\n" + pointer);
    const ProgramResult bogus = run_program("gen_switch_docs", {"--bogus"}, dir.path());
    EXPECT_EQ(bogus.exit_code, 2);
    EXPECT_EQ(bogus.err,
              "gen_switch_docs: The following argument was not expected: --bogus\n" + pointer);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace rt::test
