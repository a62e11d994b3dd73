// Whole pictures: the shipped scenes against reference images, and independence from threads.
#include <algorithm>
#include <cstdint>
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

// How the references were made, and when they may be remade.
// Each tests/data/golden/NAME.png is this renderer's own output: the shipped scene rendered with
// the case's switches, by the command below, then looked at by a person and checked in. They
// guard against change, not against a wrong model (the pixel probes, computed from the manual's
// formulas in pixel_probes_*_test.cpp, and the switch table in switch_effect_test.cpp do that).
// Remake a reference only in the commit that changes the picture on purpose (a new rule, a fixed
// bug), saying why in its message, after looking at the new picture:
//   build/bin/rt scenes/SCENE -n --quiet SWITCHES --output tests/data/golden/NAME.png
//
// Tolerance. The same build gives the same bytes; another compiler or CPU may round differently,
// and a ray that grazes an edge may then meet the other polygon. So a channel may be off by 2, and
// about 20 scattered pixels of the 204,800 (a fraction of 1e-4) by more; but no 3 x 3 square of
// wrong pixels, which is a hole, a blot or a crack, never rounding.
constexpr int kChannelTolerance = 2;
constexpr double kPixelFractionTolerance = 1e-4;
constexpr int kLargestWrongSquare = 2;
constexpr double kMeanTolerance = 0.25;

bool within_tolerance(const ImageDifference& d) {
    return d.fraction_over_threshold <= kPixelFractionTolerance &&
           d.largest_wrong_square <= kLargestWrongSquare &&
           d.mean_absolute_difference <= kMeanTolerance;
}

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
    EXPECT_TRUE(within_tolerance(d))
        << "pixels off by more than " << kChannelTolerance << ": " << d.fraction_over_threshold
        << " of them (at most " << kPixelFractionTolerance << "), the largest square of them "
        << d.largest_wrong_square << " a side (at most " << kLargestWrongSquare
        << "), mean difference " << d.mean_absolute_difference << " (at most " << kMeanTolerance
        << ")";
    if (HasFailure()) {
        const fs::path kept = fs::temp_directory_path() / ("rt-golden-" + c.name + "-got.png");
        fs::copy_file(made, kept, fs::copy_options::overwrite_existing);
        ADD_FAILURE() << "the render was kept as " << kept;
    }
}

// Regenerate a reference only as the comment at the top of this file says.
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

// The tolerance lets rounding through and stops damage: the reference itself, damaged in the ways
// a broken renderer damages a picture, must fail it.
// The rectangle turned to its opposite: white where the picture is dark, black where it is light.
Image8 damaged(Image8 image, int x0, int y0, int w, int h) {
    for (int y = y0; y < y0 + h; ++y) {
        for (int x = x0; x < x0 + w; ++x) {
            for (int c = 0; c < 3; ++c) {
                image.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                           static_cast<std::size_t>(x)) *
                              3 +
                          static_cast<std::size_t>(c)] ^= 0x80;
            }
        }
    }
    return image;
}

TEST(Golden, ToleranceAcceptsRoundingAndRejectsDamage) {
    const Image8 want = read_png(source_dir() / "tests/data/golden/twocubes.png");
    ASSERT_EQ(want.width, 512);
    // Rounding: a tenth of the channels off by 2, and 15 single pixels wholly wrong, apart.
    Image8 rounded = want;
    for (std::size_t k = 0; k < rounded.rgb.size(); k += 10) {
        std::uint8_t& v = rounded.rgb[k];
        v = static_cast<std::uint8_t>(v < 128 ? v + 2 : v - 2);
    }
    for (int k = 0; k < 15; ++k) {
        rounded = damaged(rounded, 20 + 31 * k, 40 + 23 * k, 1, 1);
    }
    EXPECT_TRUE(within_tolerance(compare_images(rounded, want, kChannelTolerance)));
    // A 180-pixel crack, a 14 x 14 hole, a 3 x 3 blot.
    const auto fails = [&](const Image8& broken) {
        return !within_tolerance(compare_images(broken, want, kChannelTolerance));
    };
    EXPECT_TRUE(fails(damaged(want, 150, 200, 180, 1)));
    EXPECT_TRUE(fails(damaged(want, 250, 150, 14, 14)));
    EXPECT_TRUE(fails(damaged(want, 250, 150, 3, 3)));
}

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
