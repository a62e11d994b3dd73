// The voxel methods through the rt program: the same picture as brute force, whatever the
// method, the octree's depth and fill; a clear error when the octree outgrows -ol.
#include <filesystem>

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

class GridRender : public ::testing::Test {
protected:
    void SetUp() override {
        fs::copy(source_dir() / "scenes", dir_.path() / "scenes", fs::copy_options::recursive);
    }
    // Renders twocubes with these switches; returns the PPM file.
    std::string render(std::vector<std::string> args) {
        const std::string out = "out" + std::to_string(++renders_) + ".ppm";
        std::vector<std::string> all = {"scenes/twocubes", "-n", "--quiet", "--output", out};
        all.insert(all.end(), args.begin(), args.end());
        const ProgramResult r = run_program("rt", all, dir_.path());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_text(dir_.path() / out);
    }

    TempDir dir_;
    int renders_ = 0;
};

TEST_F(GridRender, EveryVoxelMethodDrawsBruteForcesPicture) {
    const std::string brute = render({"--accel", "brute"});
    ASSERT_FALSE(brute.empty());
    EXPECT_EQ(render({"--accel", "seads"}), brute);
    EXPECT_EQ(render({}), brute);  // the scene header's octree of depth 4
    EXPECT_EQ(render({"-od", "0"}), brute);
    EXPECT_EQ(render({"-od", "12", "-op", "-ss", "3"}), brute);
}

TEST_F(GridRender, AnOctreeTooBigForTheOctlistIsAUsageError) {
    const ProgramResult r =
        run_program("rt", {"scenes/twocubes", "-n", "-od", "20", "-ol", "3"}, dir_.path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("-ol"), std::string::npos) << r.err;
}

TEST_F(GridRender, DebugSwitchesReportAndListTheOctree) {
    const ProgramResult r =
        run_program("rt", {"scenes/twocubes", "-n", "-ds", "-doo", "-od", "3"}, dir_.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("strike check (-ds): 0 of"), std::string::npos) << r.err;
    const std::string listing = read_text(dir_.path() / "octree.lst");
    EXPECT_EQ(listing.rfind("# octree: depth 3", 0), 0u) << listing.substr(0, 100);

    const ProgramResult seads =
        run_program("rt", {"twocubes", "-n", "-doo", "--accel", "seads"}, dir_.path() / "scenes");
    EXPECT_EQ(seads.exit_code, 0) << seads.err;
    EXPECT_NE(seads.err.find("no octree.lst written"), std::string::npos) << seads.err;
}

}  // namespace
}  // namespace rt::test
