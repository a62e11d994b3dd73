// The render arguments a .gro records for --resume: one header line that gives back the same
// command-line words, and the words the parser records from a command line.
#include <string>
#include <vector>

#include "rt/app/resume.h"
#include "rt/app/switch_parser.h"
#include "rt/app/version.h"
#include "rt/core/error.h"
#include "rt/image/gro_format.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

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

// An unfinished picture of "glass -m 2 -Dx", as an interrupted render writes it.
std::string unfinished_picture(const test::TempDir& dir) {
    Film film(4, 3, {0, 0, 3, 2});
    film.set_first_finished_row(2);
    film.provenance = {"glass",
                       "-m 2 -Dx",
                       "rt " + std::string(kVersion),
                       "2026-12-02T00:00:00Z",
                       encode_arguments({{"glass"}, {"-m", "2"}, {"-Dx"}}),
                       "0",
                       "fnv1a64:0123456789abcdef"};
    const std::string path = (dir.path() / "p.gro").string();
    write_gro(film, path);
    return path;
}

TEST(ResumePlan, TakesTheRecordedSwitchesGivenInAnyOrderOrNone) {
    const test::TempDir dir;
    const std::string path = unfinished_picture(dir);
    for (const std::vector<std::string>& given :
         {std::vector<std::string>{"--resume", path, "--threads", "3"},
          std::vector<std::string>{"-Dx", "--resume", path, "glass", "-m", "2", "--threads",
                                   "3"}}) {
        const ResumePlan plan = plan_resume(parse_command_line(given));
        EXPECT_EQ(plan.options.scene, "glass");
        EXPECT_EQ(plan.options.display.multiplier, 2.0);
        EXPECT_FALSE(plan.options.shading.sampling.adaptive);  // -Dx
        EXPECT_EQ(plan.options.threads, 3);
        EXPECT_EQ(plan.options.resume, path);
        EXPECT_EQ(plan.done.first_finished_row(), 2);
    }
}

TEST(ResumePlan, RefusesOtherSwitchesOrAnotherSeed) {
    const test::TempDir dir;
    const std::string path = unfinished_picture(dir);
    EXPECT_THROW(plan_resume(parse_command_line({"--resume", path, "glass", "-m", "3", "-Dx"})),
                 UsageError);
    EXPECT_THROW(plan_resume(parse_command_line({"--resume", path, "glass", "-m", "2"})),
                 UsageError);
    EXPECT_THROW(
        plan_resume(parse_command_line({"--resume", path, "glass", "-m", "2", "-Dx", "--seed=1"})),
        UsageError);
}

}  // namespace
}  // namespace rt
