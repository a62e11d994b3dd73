// The debugging switches print what docs/switches.md says they print (-dsp -dso -dl -dc -dx -de,
// and -p with the z-buffer), checked through the rt program on a small window of twocubes.
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

std::size_t count_starting(const std::vector<std::string>& lines, const std::string& prefix) {
    std::size_t n = 0;
    for (const std::string& line : lines) {
        n += line.rfind(prefix, 0) == 0 ? 1 : 0;
    }
    return n;
}

// twocubes (an octree of depth 4, the eye at (10, 30, -75)) with an 8 x 8 window on the cubes.
class DebugSwitches : public ::testing::Test {
protected:
    void SetUp() override {
        fs::copy(source_dir() / "scenes", dir_.path(), fs::copy_options::recursive);
        std::string scene = read_text(dir_.path() / "twocubes.scn");
        const std::string whole = "$ 0 0 511 399";
        scene.replace(scene.find(whole), whole.size(), "$ 250 180 257 187");
        dir_.write("small.scn", scene);
    }
    ProgramResult rt(std::vector<std::string> args) {
        args.insert(args.begin(), {"small", "-n"});  // not --quiet: -ds reports in a note
        ProgramResult r = run_program("rt", args, dir_.path());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return r;
    }
    TempDir dir_;
};

// The number N in "strike check (-ds): N of M rays and shadow feelers differ from brute force".
long strike_differences(const std::string& err) {
    const std::regex summary(R"(strike check \(-ds\): (\d+) of (\d+) rays)");
    std::smatch m;
    if (!std::regex_search(err, m, summary)) {
        ADD_FAILURE() << "no strike summary in:\n" << err;
        return -1;
    }
    EXPECT_GE(std::stol(m[2]), std::stol(m[1]));  // N of M: no more differences than rays
    return std::stol(m[1]);
}

TEST_F(DebugSwitches, DashDspPrintsEveryDifferenceTheStrikeCheckCounts) {
    // -tv 1 gives up after one fruitless voxel, so the octree misses what brute force finds.
    const ProgramResult r = rt({"-tv", "1", "-dsp"});
    const long differences = strike_differences(r.err);
    EXPECT_GT(differences, 10);
    const std::vector<std::string> lines = lines_of(r.err);
    EXPECT_EQ(static_cast<long>(count_starting(lines, "strike: ")), differences);
    EXPECT_GT(count_starting(lines, "strike: octree found nothing, brute force polygon "), 0U)
        << r.err;
    EXPECT_EQ(count_starting(lines, "  oct at lattice"), 0U);  // that is -dso
}

TEST_F(DebugSwitches, WithoutDifferencesDashDspPrintsOnlyTheSummary) {
    const ProgramResult r = rt({"-dsp"});
    EXPECT_EQ(strike_differences(r.err), 0);
    EXPECT_EQ(count_starting(lines_of(r.err), "strike: "), 0U);
}

// -dso: after each difference the octs the walk visited. Brute force's polygon lies in one of
// them, since a voxel walk visits every voxel the ray crosses.
TEST_F(DebugSwitches, DashDsoListsTheOctsHoldingBruteForcesPolygon) {
    const ProgramResult r = rt({"-tv", "1", "-dso"});
    const long differences = strike_differences(r.err);
    ASSERT_GT(differences, 0);
    const std::regex difference(R"(^strike: octree found nothing, brute force polygon (\d+) at)");
    const std::regex oct(
        R"(^  oct at lattice \(\d+, \d+, \d+\) side \d+ leaves at t \S+: polygons(.*)$)");
    std::vector<std::string> lines = lines_of(r.err);
    int checked = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::smatch m;
        if (!std::regex_search(lines[i], m, difference)) {
            continue;
        }
        const std::string polygon = m[1];
        bool listed = false;
        std::size_t octs = 0;
        for (std::size_t k = i + 1; k < lines.size() && lines[k].rfind("  ", 0) == 0; ++k) {
            std::smatch o;
            ASSERT_TRUE(std::regex_match(lines[k], o, oct)) << lines[k];
            ++octs;
            std::istringstream ids(o[1]);
            for (std::string id; ids >> id;) {
                listed |= id == polygon;
            }
        }
        EXPECT_GT(octs, 0U) << lines[i];
        EXPECT_TRUE(listed) << lines[i];
        ++checked;
    }
    EXPECT_GT(checked, 0);
}

TEST_F(DebugSwitches, DashDsoWithSeadsListsVoxels) {
    const ProgramResult r = rt({"--accel", "seads", "-tv", "1", "-dso"});
    ASSERT_GT(strike_differences(r.err), 0);
    EXPECT_GT(count_starting(lines_of(r.err), "  voxel ("), 0U) << r.err;
}

// -dl: one line per nearest-hit query. The methods agree bit for bit, so the log is the same
// whatever the method.
TEST_F(DebugSwitches, DashDlLogsTheSameQueriesAndAnswersWhateverTheMethod) {
    const auto log = [&](const std::string& method) {
        std::vector<std::string> lines =
            lines_of(rt({"-dl", "--threads", "1", "--accel", method}).err);
        std::erase_if(lines,
                      [](const std::string& l) { return l.rfind("intersection: ", 0) != 0; });
        return lines;
    };
    const std::vector<std::string> brute = log("brute");
    const std::vector<std::string> octree = log("octree");
    const std::vector<std::string> bvh = log("bvh");
    EXPECT_GE(brute.size(), 64U);  // at least the eye rays
    const std::regex form(
        R"(^intersection: origin \(\S+, \S+, \S+\) direction \(\S+, \S+, \S+\) t \(\S+, \S+\) -> (nothing|polygon \d+ at t \S+)$)");
    for (const std::string& line : brute) {
        EXPECT_TRUE(std::regex_match(line, form)) << line;
    }
    EXPECT_EQ(octree, brute);
    EXPECT_EQ(bvh, brute);
}

// -dc: the pixel each sample is for, as "line Y column X", rows from the bottom up.
TEST_F(DebugSwitches, DashDcNamesEveryPixelBottomRowFirst) {
    const std::vector<std::string> lines = lines_of(rt({"-dc", "--threads", "1", "-Dx"}).err);
    std::map<std::pair<int, int>, int> seen;
    int first_row = -1;
    const std::regex form(R"(^line (\d+) column (\d+)$)");
    for (const std::string& line : lines) {
        std::smatch m;
        if (std::regex_match(line, m, form)) {
            const int y = std::stoi(m[1]);
            ++seen[{std::stoi(m[2]), y}];
            if (first_row < 0) {
                first_row = y;
            }
        }
    }
    EXPECT_EQ(seen.size(), 64U);
    for (const auto& [pixel, count] : seen) {
        EXPECT_GE(pixel.first, 250);
        EXPECT_LE(pixel.first, 257);
        EXPECT_GE(pixel.second, 180);
        EXPECT_LE(pixel.second, 187);
        EXPECT_GE(count, 1);
    }
    EXPECT_EQ(first_row, 187);
}

// -dx: per pixel, the samples taken and the rays distributed. With a sample resolution of 2, -Dx
// takes all 2 x 2 samples of every pixel; adaptive sampling takes at most that many.
TEST_F(DebugSwitches, DashDxReportsTheSamplesOfEveryPixel) {
    std::string scene = read_text(dir_.path() / "small.scn");
    scene.replace(scene.find("$ 1\n"), 4, "$ 2\n");
    dir_.write("small.scn", scene);
    const std::regex form(
        R"(^pixel (\d+) (\d+): (\d+) samples, (\d+) intersections distributing (\d+) rays, (\d+) probes$)");
    for (const bool every_sample : {true, false}) {
        std::vector<std::string> args{"-dx"};
        if (every_sample) {
            args.push_back("-Dx");
        }
        std::map<std::pair<int, int>, int> samples;
        for (const std::string& line : lines_of(rt(args).err)) {
            std::smatch m;
            if (std::regex_match(line, m, form)) {
                samples[{std::stoi(m[1]), std::stoi(m[2])}] = std::stoi(m[3]);
            }
        }
        EXPECT_EQ(samples.size(), 64U);
        int fewer = 0;
        for (const auto& [pixel, n] : samples) {
            EXPECT_GE(n, 1);
            EXPECT_LE(n, 4);
            if (every_sample) {
                EXPECT_EQ(n, 4) << pixel.first << " " << pixel.second;
            }
            fewer += n < 4 ? 1 : 0;
        }
        if (!every_sample) {
            EXPECT_GT(fewer, 0);  // the cube's flat faces need fewer than all four
        }
    }
}

// -de: the culled rays are traced again and none hits; the figures come at the end, as -p's do.
TEST_F(DebugSwitches, DashDeReportsCulledRaysThatHitNothing) {
    const ProgramResult r = rt({"-de"});
    const std::regex check(
        R"(exit culling check \(-de\): (\d+) culled rays re-traced, (\d+) hit something)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, check)) << r.out;
    EXPECT_EQ(m[2], "0");
    EXPECT_NE(r.out.find("exit culling: "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("wrongly culled"), std::string::npos) << r.out;
}

TEST_F(DebugSwitches, DashPWithTheZBufferReportsIt) {
    const ProgramResult r = rt({"-p", "--zbuffer"});
    const std::regex zbuffer(
        R"(z-buffer: (\d+) polygons in view, (\d+) pixel entries \(at most (\d+) in a pixel\))");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, zbuffer)) << r.out;
    EXPECT_GT(std::stol(m[1]), 0);
    EXPECT_GE(std::stol(m[2]), std::stol(m[3]));
}

TEST_F(DebugSwitches, DashDofWithoutDashOpSaysThereIsNothingToTrace) {
    const ProgramResult r = run_program("rt", {"small", "-n", "-dof"}, dir_.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("rt: -dof traces the -op octree fill only; nothing to trace here"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("fill-plane level"), std::string::npos) << r.err;
}

TEST_F(DebugSwitches, AnUnknownAccelIsAUsageError) {
    const ProgramResult r = run_program("rt", {"small", "-n", "--accel", "grid"}, dir_.path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("rt: --accel: expected brute, octree, seads, bvh or embree, found 'grid'"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace rt::test
