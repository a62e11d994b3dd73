// The render arguments a .gro records for --resume: one header line that gives back the same
// command-line words, and the words the parser records from a command line.
#include <string>
#include <vector>

#include "rt/app/resume.h"
#include "rt/app/switch_parser.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(ResumeArguments, WordsWithSpacesAndBackslashesComeBackAsTheyWere) {
    const std::vector<std::vector<std::string>> arguments = {
        {"my scenes/two cubes"}, {"-m", "2.0"}, {"--model", "a\\b c\\\\s.ply"}, {"-Dx"}};
    const std::string text = encode_arguments(arguments);
    EXPECT_EQ(text.find('\n'), std::string::npos);
    EXPECT_EQ(text, "my\\sscenes/two\\scubes -m 2.0 --model a\\\\b\\sc\\\\\\\\s.ply -Dx");
    EXPECT_EQ(decode_arguments(text),
              (std::vector<std::string>{"my scenes/two cubes", "-m", "2.0", "--model",
                                        "a\\b c\\\\s.ply", "-Dx"}));
}

// Only what decides the picture is recorded: --output, --threads, --quiet and --no-window are
// not, --seed and --cutoff are.
TEST(ResumeArguments, TheParserRecordsTheSceneAndThePictureSwitches) {
    const Options o =
        parse_command_line({"-m", "2", "twocubes", "--output", "a.png", "--threads", "2",
                            "--seed=7", "--quiet", "--cutoff", "0.1", "--no-window", "-Dx"});
    EXPECT_EQ(o.render_arguments,
              (std::vector<std::vector<std::string>>{
                  {"twocubes"}, {"-m", "2"}, {"--seed=7"}, {"--cutoff", "0.1"}, {"-Dx"}}));
}

TEST(ResumeArguments, ResumeNeedsNoScene) {
    const Options o = parse_command_line({"--resume", "twocubes.gro", "--threads", "2"});
    EXPECT_EQ(o.resume, "twocubes.gro");
    EXPECT_TRUE(o.render_arguments.empty());
}

}  // namespace
}  // namespace rt
