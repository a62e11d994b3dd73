// rt --tile I/N and merge (docs/distributed.md): the parts of a render, merged, are the single
// render pixel for pixel; parts of different renders, missing or repeated parts are refused.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/hand_readers.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

class TileMerge : public ::testing::Test {
protected:
    void SetUp() override {
        fs::copy(source_dir() / "scenes", dir_.path() / "scenes", fs::copy_options::recursive);
        // A 64 x 47 window of twocubes: the cube's edge, its shadow and the checkerboard.
        std::string scene = read_text(at("scenes/twocubes.scn"));
        const std::string whole = "$ 0 0 511 399";
        scene.replace(scene.find(whole), whole.size(), "$ 200 180 263 226");
        dir_.write("scenes/small.scn", scene);
    }
    ProgramResult run(const std::string& program, const std::vector<std::string>& args) {
        return run_program(program, args, dir_.path());
    }
    // rt scenes/small SWITCHES --tile I/N, for every I; returns the part files' names.
    std::vector<std::string> render_parts(int count, const std::vector<std::string>& switches) {
        std::vector<std::string> parts;
        for (int i = 1; i <= count; ++i) {
            std::vector<std::string> args{"scenes/small"};
            args.insert(args.end(), switches.begin(), switches.end());
            args.insert(args.end(), {"--tile", std::to_string(i) + "/" + std::to_string(count)});
            const ProgramResult r = run("rt", args);
            EXPECT_EQ(r.exit_code, 0) << r.err;
            parts.push_back("small.part-" + std::to_string(i) + "-of-" + std::to_string(count) +
                            ".gro");
            EXPECT_TRUE(fs::exists(at(parts.back()))) << parts.back();
        }
        return parts;
    }
    fs::path at(const std::string& name) const { return dir_.path() / name; }

    TempDir dir_;
};

void expect_same_pixels(const GroPixels& a, const GroPixels& b) {
    EXPECT_EQ(a.left, b.left);
    EXPECT_EQ(a.top, b.top);
    EXPECT_EQ(a.right, b.right);
    EXPECT_EQ(a.bottom, b.bottom);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        differing += a.pixels[i] != b.pixels[i] ? 1 : 0;  // bit for bit: no tolerance
    }
    EXPECT_EQ(differing, 0u) << "of " << a.pixels.size() << " pixels";
}

TEST_F(TileMerge, ThreePartsMergedAreTheSingleRenderPixelForPixel) {
    for (const std::vector<std::string>& switches :
         {std::vector<std::string>{"--seed", "5", "--threads", "2"},
          std::vector<std::string>{"-L", "220", "-Dd", "--threads", "1"}}) {
        SCOPED_TRACE(switches.front());
        std::vector<std::string> single{"scenes/small"};
        single.insert(single.end(), switches.begin(), switches.end());
        single.insert(single.end(), {"--output", "single.ppm"});
        const ProgramResult whole = run("rt", single);
        ASSERT_EQ(whole.exit_code, 0) << whole.err;
        fs::rename(at("small.gro"), at("single.gro"));

        std::vector<std::string> parts = render_parts(3, switches);
        std::swap(parts[0], parts[2]);  // any order
        parts.insert(parts.end(), {"--output", "merged.ppm"});
        const ProgramResult merged = run("merge", parts);
        ASSERT_EQ(merged.exit_code, 0) << merged.err;

        const GroPixels a = parse_gro(at("single.gro"));
        const GroPixels b = parse_gro(at("small.gro"));
        expect_same_pixels(a, b);
        EXPECT_EQ(a.header.at("scene"), b.header.at("scene"));
        EXPECT_EQ(a.header.at("switches"), b.header.at("switches"));
        EXPECT_EQ(b.header.count("part"), 0u);
        EXPECT_TRUE(read_text(at("single.ppm")) == read_text(at("merged.ppm")));
    }
}

TEST_F(TileMerge, MissingPartsAreNamedAndNothingIsWritten) {
    const std::vector<std::string> parts = render_parts(4, {"-Dd"});
    dir_.write("small.gro", "an earlier picture");
    const ProgramResult r = run("merge", {parts[1], parts[2]});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("missing parts 1 and 4 of 4"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(at("small.gro")), "an earlier picture");
}

TEST_F(TileMerge, PartsOfAnotherRenderAreRefused) {
    const std::vector<std::string> parts = render_parts(2, {"-Dd", "--seed", "5"});
    fs::rename(at(parts[0]), at("first5.gro"));
    render_parts(2, {"-Dd", "--seed", "6"});
    const ProgramResult seeds = run("merge", {"first5.gro", parts[1]});
    EXPECT_EQ(seeds.exit_code, 1);
    // The first line that differs is `arguments`, the scene and the switches that decide pixels.
    EXPECT_NE(seeds.err.find("a part of another render: its arguments is '"), std::string::npos)
        << seeds.err;
    EXPECT_NE(seeds.err.find("-Dd --seed 6', first5.gro's is '"), std::string::npos) << seeds.err;
    EXPECT_NE(seeds.err.find("-Dd --seed 5'"), std::string::npos) << seeds.err;

    render_parts(2, {"-Dd", "-Dr", "--seed", "5"});
    const ProgramResult switches = run("merge", {"first5.gro", parts[1]});
    EXPECT_EQ(switches.exit_code, 1);
    EXPECT_NE(switches.err.find("its switches is '-Dd -Dr'"), std::string::npos) << switches.err;
    EXPECT_FALSE(fs::exists(at("small.gro")));
}

TEST_F(TileMerge, TheSamePartTwiceIsRefused) {
    const std::vector<std::string> parts = render_parts(2, {"-Dd"});
    fs::copy_file(at(parts[0]), at("copy.gro"));
    const ProgramResult r = run("merge", {parts[0], parts[1], "copy.gro"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("part 1 is given twice"), std::string::npos) << r.err;
}

TEST_F(TileMerge, AWholePictureIsNotAPart) {
    ASSERT_EQ(run("rt", {"scenes/small", "-Dd"}).exit_code, 0);
    const ProgramResult r = run("merge", {"small.gro"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("not a part file"), std::string::npos) << r.err;
}

TEST_F(TileMerge, RtRefusesABadTile) {
    const ProgramResult zero = run("rt", {"scenes/small", "--tile", "0/3"});
    EXPECT_EQ(zero.exit_code, 2);
    EXPECT_NE(zero.err.find("--tile: expected I/N"), std::string::npos) << zero.err;
    const ProgramResult output = run("rt", {"scenes/small", "--tile", "1/3", "--output", "a.png"});
    EXPECT_EQ(output.exit_code, 2);
    EXPECT_NE(output.err.find("merge writes the images"), std::string::npos) << output.err;
    const ProgramResult too_many = run("rt", {"scenes/small", "--tile", "1/48"});
    EXPECT_EQ(too_many.exit_code, 2);
    EXPECT_NE(too_many.err.find("47 rows into 48 parts"), std::string::npos) << too_many.err;
}

}  // namespace
}  // namespace rt::test
