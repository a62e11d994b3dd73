// Whole pictures: the shipped scenes against reference images, and independence from threads.
#include <algorithm>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "rt/image/compare.h"
#include "rt/image/png_format.h"

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// Tolerance: references are regenerated only on purpose; a render may differ from its reference
// by rounding (a channel off by 2 or less) and in at most 0.1 % of pixels by more, e.g. where a
// ray grazes an edge and another compiler's arithmetic decides differently.
constexpr int kChannelTolerance = 2;
constexpr double kPixelFractionTolerance = 0.001;
constexpr double kMeanTolerance = 0.25;

fs::path render(const TempDir& dir, const std::string& scene, const std::string& output,
                const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args{(source_dir() / "scenes" / scene).string(), "-n", "--quiet",
                                  "--output", output};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProgramResult r = run_program("rt", args, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir.path() / output;
}

// One shipped scene under one combination of switches, and the reference it must match.
struct GoldenCase {
    std::string name;  ///< tests/data/golden/<name>.png
    std::string scene;
    std::vector<std::string> switches;
};

std::ostream& operator<<(std::ostream& out, const GoldenCase& c) {
    return out << c.name;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesItsReference) {
    const GoldenCase& c = GetParam();
    const TempDir dir;
    const fs::path made = render(dir, c.scene, c.name + ".png", c.switches);
    const Image8 got = read_png(made);
    const Image8 want = read_png(source_dir() / "tests/data/golden" / (c.name + ".png"));
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    const ImageDifference d = compare_images(got, want, kChannelTolerance);
    EXPECT_LE(d.fraction_over_threshold, kPixelFractionTolerance);
    EXPECT_LE(d.mean_absolute_difference, kMeanTolerance);
    if (HasFailure()) {
        const fs::path kept = fs::temp_directory_path() / ("rt-golden-" + c.name + "-got.png");
        fs::copy_file(made, kept, fs::copy_options::overwrite_existing);
        ADD_FAILURE() << "the render was kept as " << kept;
    }
}

// Regenerate a reference, on purpose only, with
//   build/bin/rt scenes/SCENE -n --quiet SWITCHES --output tests/data/golden/NAME.png
INSTANTIATE_TEST_SUITE_P(
    Shipped, Golden,
    ::testing::Values(GoldenCase{"twocubes", "twocubes", {}},
                      GoldenCase{"twocubes-Dd", "twocubes", {"-Dd"}},
                      GoldenCase{"twocubes-Ds", "twocubes", {"-Ds"}},
                      GoldenCase{"twocubes-Stb-Cf", "twocubes", {"-Stb0.3", "-Cf"}},
                      GoldenCase{"twocubes-Sg-Co", "twocubes", {"-Sg", "-Co"}},
                      GoldenCase{"twocubes-Wr-T", "twocubes", {"-Wr", "-T"}},
                      GoldenCase{"twocubes-K-Da", "twocubes", {"-K", "-Da"}},
                      GoldenCase{"twocubes-F-I", "twocubes", {"-F0.05,4", "-I", "--seed", "3"}},
                      GoldenCase{"twocubes-Oi", "twocubes", {"-Oi"}}),
    [](const ::testing::TestParamInfo<GoldenCase>& case_info) {
        std::string name = case_info.param.name;
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

TEST(Golden, SamePictureWhateverTheThreadCount) {
    const TempDir dir;
    const std::string one = read_text(render(dir, "twocubes", "one.ppm", {"--threads", "1"}));
    const std::string two = read_text(render(dir, "twocubes", "two.ppm", {"--threads", "2"}));
    const std::string five = read_text(render(dir, "twocubes", "five.ppm", {"--threads", "5"}));
    ASSERT_FALSE(one.empty());
    EXPECT_TRUE(one == two);
    EXPECT_TRUE(one == five);
}

}  // namespace
}  // namespace rt::test

namespace rt::test {
namespace {

// Every intersection method, with and without exit culling and the z-buffer, gives the same
// picture bit for bit (manual 3.1: they differ in speed only).
TEST(SamePicture, WhateverTheIntersectionMethod) {
    const TempDir dir;
    const std::vector<std::string> common{"-Dd", "--seed", "5"};
    const auto picture = [&](const std::string& name, std::vector<std::string> extra) {
        extra.insert(extra.end(), common.begin(), common.end());
        return read_text(render(dir, "twocubes", name + ".ppm", extra));
    };
    const std::string reference = picture("brute", {"--accel", "brute", "-De"});
    ASSERT_FALSE(reference.empty());
    for (const std::vector<std::string>& method :
         std::vector<std::vector<std::string>>{{"--accel", "brute"},
                                               {"--accel", "brute", "--zbuffer"},
                                               {"--accel", "seads"},
             {"--accel", "octree"},
             {"--accel", "octree", "-od3", "-on"},
             {"--accel", "octree", "-op", "--zbuffer"},
             {"--accel", "bvh"},
             {"--accel", "bvh", "-De"},
                                               {"--accel", "seads", "-De", "--zbuffer"}}) {
        std::string name = "method";
        for (const std::string& word : method) {
            name.append("_").append(word.substr(word.find_first_not_of('-')));
        }
        EXPECT_TRUE(picture(name, method) == reference) << name;
    }
}

}  // namespace
}  // namespace rt::test
