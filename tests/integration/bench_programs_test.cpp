// The programs in bench/ as a user meets them: each option read, and bad command lines refused
// with exit code 2 and a message naming the option. They are built only with
// RT_BUILD_BENCHMARKS=ON; otherwise these tests skip. The workloads are tiny: a test checks the
// command line, not the figures.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"
#include <sched.h>

namespace rt::test {
namespace {

namespace fs = std::filesystem;

class BenchProgram : public ::testing::Test {
protected:
    void SetUp() override {
#ifndef RT_BENCHMARKS_BUILT
        GTEST_SKIP() << "the bench programs are built with -DRT_BUILD_BENCHMARKS=ON";
#endif
    }
    ProgramResult run(const std::string& program, const std::vector<std::string>& args) const {
        return run_program(program, args, dir_.path());
    }
    std::vector<std::string> lines(const std::string& file) const {
        std::vector<std::string> out;
        const std::string text = read_text(dir_.path() / file);
        std::size_t start = 0;
        while (start < text.size()) {
            const std::size_t end = text.find('\n', start);
            out.push_back(text.substr(start, end - start));
            start = end == std::string::npos ? text.size() : end + 1;
        }
        return out;
    }
    static std::string twocubes() {
        return (source_dir() / "scenes" / "twocubes").string();
    }

    TempDir dir_;
};

// The index-th comma-separated field of a CSV line.
std::string field(const std::string& line, int index) {
    std::size_t start = 0;
    for (int i = 0; i < index; ++i) {
        start = line.find(',', start) + 1;
    }
    return line.substr(start, line.find(',', start) - start);
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The lowest-numbered CPU this process may run on, for --pin.
int first_allowed_cpu() {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    sched_getaffinity(0, sizeof allowed, &allowed);
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
        if (CPU_ISSET(static_cast<std::size_t>(cpu), &allowed)) {
            return cpu;
        }
    }
    return 0;
}

// Exit code 2, nothing measured, and "PROGRAM: message" with a pointer to --help.
void expect_usage_error(const ProgramResult& r, const std::string& program,
                        const std::string& message) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err, program + ": " + message + "\n" + program + ": run '" + program +
                         " --help' for the options\n");
    EXPECT_EQ(r.out, "");
}

void expect_help_lists(const ProgramResult& r, const std::vector<std::string>& options) {
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "Usage: ")) << r.out;
    for (const std::string& option : options) {
        EXPECT_TRUE(contains(r.out, "  " + option + " ")) << option << " missing from\n" << r.out;
    }
}

TEST_F(BenchProgram, LabReadsEveryOption) {
    // --quick first: the --sizes and --seconds after it override it.
    const ProgramResult r = run("rt_lab", {"--quick",
                                           "--sizes",
                                           "1k",
                                           "--meshes",
                                           "sphere,twocubes",
                                           "--accels",
                                           "bvh,seads",
                                           "--threads",
                                           "1",
                                           "--seconds=0.001",
                                           "--seads-side",
                                           "4",
                                           "--octree-depth",
                                           "3",
                                           "--csv",
                                           "lab.csv",
                                           "--svg",
                                           "lab.svg",
                                           "--source",
                                           source_dir().string(),
                                           "--pin",
                                           std::to_string(first_allowed_cpu())});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> csv = lines("lab.csv");
    ASSERT_EQ(csv.size(), 5U) << r.out;  // a header, then two meshes by two methods
    EXPECT_TRUE(csv[1].starts_with("sphere,960,bvh,")) << csv[1];  // 1k: the nearest sphere
    EXPECT_TRUE(csv[2].starts_with("sphere,960,seads,")) << csv[2];
    EXPECT_TRUE(csv[3].starts_with("twocubes,142,bvh,")) << csv[3];
    EXPECT_TRUE(csv[4].starts_with("twocubes,142,seads,")) << csv[4];
    for (std::size_t row = 1; row < csv.size(); ++row) {
        EXPECT_EQ(field(csv[row], 5), "1") << csv[row];  // threads
    }
    // The BVH's tree cost (nodes, packets, leaves in pairs) ends its rows; the other methods
    // leave it empty.
    EXPECT_TRUE(csv[0].ends_with(",tree_cost_nodes,tree_cost_leaves,tree_cost_leaf_pairs,round"))
        << csv[0];
    EXPECT_GE(std::stod(field(csv[1], 20)), 1.0) << csv[1];  // the root at least
    EXPECT_GT(std::stod(field(csv[1], 21)), 0.0) << csv[1];
    EXPECT_GT(std::stod(field(csv[1], 22)), 0.0) << csv[1];
    EXPECT_TRUE(csv[2].ends_with(",,,,1")) << csv[2];  // and the round, the only one
    EXPECT_TRUE(contains(r.out, "tree cost")) << r.out;
    EXPECT_TRUE(contains(
        r.out, "\none-thread runs on CPU " + std::to_string(first_allowed_cpu()) + " (--pin)\n"))
        << r.out;
    EXPECT_TRUE(contains(read_text(dir_.path() / "lab.svg"), "<svg"));
}

// The numbers in a line, in order: "sphere 960 bvh 0.55 (0.03-0.67)" gives 960, 0.55, 0.03, 0.67
// (a range's dash is not a minus sign: the shares are never negative).
std::vector<double> numbers_in(const std::string& line) {
    std::vector<double> out;
    for (std::size_t i = 0; i < line.size();) {
        if (std::isdigit(static_cast<unsigned char>(line[i])) != 0) {
            std::size_t used = 0;
            out.push_back(std::stod(line.substr(i), &used));
            i += used;
        } else {
            ++i;
        }
    }
    return out;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

TEST_F(BenchProgram, LabRoundsGiveSharesOfEmbreeWithTheirSpread) {
#ifndef RT_WITH_EMBREE
    GTEST_SKIP() << "Embree is not built into this rt";
#endif
    const ProgramResult r =
        run("rt_lab", {"--sizes", "1k", "--meshes", "sphere", "--accels", "bvh,embree", "--rounds",
                       "3", "--seconds", "0.001", "--threads", "1", "--csv", "lab.csv"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // Every round measures both; even rounds take the methods backward.
    const std::vector<std::string> csv = lines("lab.csv");
    ASSERT_EQ(csv.size(), 7U) << r.out;
    EXPECT_TRUE(csv[0].ends_with(",round")) << csv[0];
    const std::vector<std::string> order{"bvh", "embree", "embree", "bvh", "bvh", "embree"};
    std::vector<double> bvh_camera;
    std::vector<double> embree_camera;
    for (std::size_t row = 1; row < csv.size(); ++row) {
        EXPECT_EQ(field(csv[row], 2), order[row - 1]) << csv[row];
        EXPECT_EQ(field(csv[row], 23), std::to_string((row + 1) / 2)) << csv[row];
        (field(csv[row], 2) == "bvh" ? bvh_camera : embree_camera)
            .push_back(std::stod(field(csv[row], 6)));
    }
    EXPECT_TRUE(contains(r.out, "round 3 of 3\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "median (lowest-highest) of 3 rounds")) << r.out;
    // The BVH's row: build, then camera rays over Embree's in the same round, median and range.
    const std::size_t at = r.out.find("\nsphere           960 bvh ", r.out.find("Shares of"));
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string row = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
    const std::vector<double> figures = numbers_in(row);
    ASSERT_EQ(figures.size(), 1U + 6U * 3U) << row;  // the triangles, then six cells of three
    std::vector<double> shares;
    for (std::size_t i = 0; i < bvh_camera.size(); ++i) {
        shares.push_back(bvh_camera[i] / embree_camera[i]);
    }
    // The CSV's rates have four decimals, the table's shares two.
    EXPECT_NEAR(figures[4], median(shares), 0.006) << row;
    EXPECT_NEAR(figures[5], *std::min_element(shares.begin(), shares.end()), 0.006) << row;
    EXPECT_NEAR(figures[6], *std::max_element(shares.begin(), shares.end()), 0.006) << row;
    EXPECT_LE(figures[5], figures[4]);
    EXPECT_LE(figures[4], figures[6]);
}

TEST_F(BenchProgram, LabRefusesBadCommandLines) {
    expect_usage_error(run("rt_lab", {"--bogus"}), "rt_lab",
                       "The following argument was not expected: --bogus");
    expect_usage_error(run("rt_lab", {"--quick", "--csv"}), "rt_lab",
                       "--csv: 1 required FILE missing");
    expect_usage_error(run("rt_lab", {"--sizes", "10x"}), "rt_lab",
                       "--sizes: expected a count like 1000, 10k or 1M, found '10x'");
    expect_usage_error(run("rt_lab", {"--meshes", "cube"}), "rt_lab",
                       "--meshes: cube not in {sphere,soup,twocubes}");
    expect_usage_error(run("rt_lab", {"--accels", "bvh,kd"}), "rt_lab",
                       "--accels: unknown intersection method 'kd' (brute, octree, seads, bvh, "
                       "embree)");
    expect_usage_error(run("rt_lab", {"--seconds", "0"}), "rt_lab",
                       "--seconds: expected a number above 0, found '0'");
    expect_usage_error(run("rt_lab", {"--rounds", "0"}), "rt_lab",
                       "--rounds: expected a number of rounds from 1 to 1000, found '0'");
    expect_usage_error(run("rt_lab", {"--rounds", "1001"}), "rt_lab",
                       "--rounds: expected a number of rounds from 1 to 1000, found '1001'");
    expect_usage_error(run("rt_lab", {"--threads", "0"}), "rt_lab",
                       "--threads: expected a count like 1000, 10k or 1M, found '0'");
    // A CPU the process may not run on (the list of those it may depends on the machine).
    const ProgramResult pin = run("rt_lab", {"--pin", std::to_string(CPU_SETSIZE)});
    EXPECT_EQ(pin.exit_code, 2) << pin.err;
    EXPECT_TRUE(pin.err.starts_with("rt_lab: --pin: expected one of this process's CPUs ("))
        << pin.err;
    EXPECT_TRUE(contains(pin.err, "), found '" + std::to_string(CPU_SETSIZE) + "'\n")) << pin.err;
    EXPECT_EQ(pin.out, "");
    expect_help_lists(run("rt_lab", {"--help"}),
                      {"--quick", "--sizes LIST", "--meshes LIST", "--accels LIST", "--threads N",
                       "--seconds S", "--seads-side N", "--octree-depth N", "--csv FILE",
                       "--svg FILE", "--source DIR", "--pin CPU", "--rounds N"});
}

TEST_F(BenchProgram, SceneBenchTakesItsOptionsAndPassesTheRestToRt) {
    const ProgramResult r = run("rt_scene_bench", {"--repeat", "2", twocubes(), "-L", "3",
                                                   "--csv=bench.csv", "--threads", "1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "512x4 pixels")) << r.out;  // rt's -L 3
    EXPECT_TRUE(contains(r.out, "threads      1\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "renders      2:")) << r.out;
    const std::vector<std::string> csv = lines("bench.csv");
    ASSERT_EQ(csv.size(), 2U);
    EXPECT_TRUE(contains(csv[1], ",1,512,4,2,")) << csv[1];  // threads, width, height, renders
}

TEST_F(BenchProgram, SceneBenchRefusesBadCommandLines) {
    expect_usage_error(run("rt_scene_bench", {"--repeat", "0", twocubes()}), "rt_scene_bench",
                       "--repeat: expected a whole number of at least 1, found '0'");
    expect_usage_error(run("rt_scene_bench", {twocubes(), "--repeat"}), "rt_scene_bench",
                       "--repeat: 1 required N missing");
    // An unknown switch goes to rt's parser, which refuses it the same way.
    expect_usage_error(run("rt_scene_bench", {twocubes(), "--bogus"}), "rt_scene_bench",
                       "unknown switch '--bogus'");
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{}, std::vector<std::string>{"--help"}}) {
        expect_help_lists(run("rt_scene_bench", args), {"--repeat N", "--csv FILE", "--help"});
    }
}

TEST_F(BenchProgram, AdaptiveStudyReadsEveryOption) {
    const ProgramResult r =
        run("rt_adaptive_study",
            {"--seeds", "1", "--reference", "2x2", "--reference-renders", "2", "--window",
             "100,100,102,101", "--uniform", "1x1", "--uniform=2", "--adaptive",
             "2x2@0.5,2@0.1/0.2:0.3", "--csv", "study.csv", twocubes(), "--threads", "1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "window 100 100 102 101 (3 x 2)")) << r.out;
    EXPECT_TRUE(contains(r.out, "the mean of 2 renders uniform 2x2")) << r.out;
    const std::vector<std::string> csv = lines("study.csv");
    ASSERT_EQ(csv.size(), 5U);  // a header, then four plans at one seed each
    EXPECT_TRUE(csv[1].starts_with("uniform 1x1,1,1,0,")) << csv[1];
    EXPECT_TRUE(csv[2].starts_with("uniform 2x2,2,2,0,")) << csv[2];
    EXPECT_TRUE(csv[3].starts_with("adaptive 2x2 @0.5,2,2,1,0.5,0.5,0.2,1,")) << csv[3];
    EXPECT_TRUE(csv[4].starts_with("adaptive 2x2 @0.1/0.2:0.3,2,2,1,0.1,0.2,0.3,1,")) << csv[4];
}

// A list is one word, so the scene may follow it at once (bench/README.md's example does).
TEST_F(BenchProgram, AdaptiveStudyListTakesOneWordBeforeTheScene) {
    const ProgramResult r =
        run("rt_adaptive_study",
            {"--seeds", "1", "--reference", "2x2", "--reference-renders", "2", "--window",
             "100,100,101,100", "--uniform", "1x1", "--adaptive", "2x2@0.5", twocubes()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "adaptive 2x2 @0.5")) << r.out;
}

TEST_F(BenchProgram, AdaptiveStudyRefusesBadCommandLines) {
    const std::string study = "rt_adaptive_study";
    const auto refused = [&](const std::vector<std::string>& args, const std::string& message) {
        std::vector<std::string> with_scene = args;
        with_scene.push_back(twocubes());
        expect_usage_error(run(study, with_scene), study, message);
    };
    refused({"--seeds", "0"}, "--seeds: expected a whole number of at least 1, found '0'");
    refused({"--reference", "2x2x2"},
            "--reference: expected a sample resolution NxM, found '2x2x2'");
    refused({"--reference-renders", "1"},
            "--reference-renders: expected a whole number of at least 2, found '1'");
    refused({"--window", "1,2,3"}, "--window: expected left,top,right,bottom, found '1,2,3'");
    refused({"--window", "5,5,4,4"}, "--window: empty window '5,5,4,4'");
    refused({"--uniform", "2x0"}, "--uniform: expected a positive number, found '0'");
    refused({"--adaptive", "4x4@0.1/0.2/0.3"},
            "--adaptive: expected NxM@pvar/rvar:prob, found '4x4@0.1/0.2/0.3'");
    refused({"-Q"}, "unknown switch '-Q'");
    expect_usage_error(run(study, {twocubes(), "--csv"}), study, "--csv: 1 required FILE missing");
    expect_help_lists(run(study, {"--help"}),
                      {"--seeds N", "--reference NxM", "--reference-renders M", "--window l,t,r,b",
                       "--uniform LIST", "--adaptive LIST", "--csv FILE"});
}

TEST_F(BenchProgram, VoxelBenchReadsItsArgumentsAndVariables) {
    const ProgramResult octree =
        run("rt_voxel_bench", {"1000", "100", "1000", "--only", "octree", "--depth", "3"});
    ASSERT_EQ(octree.exit_code, 0) << octree.err;
    EXPECT_TRUE(octree.out.starts_with("octree       972 tris  param   3 ")) << octree.out;
    EXPECT_EQ(std::count(octree.out.begin(), octree.out.end(), '\n'), 1) << octree.out;
    // The variables say the same as the options.
    ::setenv("ONLY", "seads", 1);  // NOLINT(concurrency-mt-unsafe)
    ::setenv("SIDE", "7", 1);      // NOLINT(concurrency-mt-unsafe)
    const ProgramResult seads = run("rt_voxel_bench", {"1000", "100"});
    ::unsetenv("ONLY");  // NOLINT(concurrency-mt-unsafe)
    ::unsetenv("SIDE");  // NOLINT(concurrency-mt-unsafe)
    ASSERT_EQ(seads.exit_code, 0) << seads.err;
    EXPECT_TRUE(seads.out.starts_with("SEADS        972 tris  param   7 ")) << seads.out;
    EXPECT_EQ(std::count(seads.out.begin(), seads.out.end(), '\n'), 1) << seads.out;
}

TEST_F(BenchProgram, VoxelBenchRefusesBadCommandLines) {
    const std::string bench = "rt_voxel_bench";
    expect_usage_error(run(bench, {"x"}), bench,
                       "max_triangles: expected a whole number of at least 1, found 'x'");
    expect_usage_error(run(bench, {"1000", "100", "1000", "4"}), bench,
                       "The following argument was not expected: 4");
    expect_usage_error(run(bench, {"--only", "bvh"}), bench, "--only: bvh not in {seads,octree}");
    expect_usage_error(run(bench, {"--side"}), bench, "--side: 1 required N missing");
    ::setenv("DEPTH", "0", 1);  // NOLINT(concurrency-mt-unsafe)
    const ProgramResult depth = run(bench, {"1000", "100"});
    ::unsetenv("DEPTH");  // NOLINT(concurrency-mt-unsafe)
    expect_usage_error(depth, bench, "--depth: expected a whole number of at least 1, found '0'");
    expect_help_lists(run(bench, {"--help"}),
                      {"max_triangles", "rays", "min_triangles", "--only NAME (Env:ONLY)",
                       "--side N (Env:SIDE)", "--depth N (Env:DEPTH)"});
}

}  // namespace
}  // namespace rt::test
