// What rt says before a render it could not finish or show: too little memory for the view, an
// output folder that takes no files, polygons between the eye and the screen.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// A 2 x 2 square in the plane z = 0, facing the eye at z = -10.
const char* const kFacingSquare =
    "4\n0 -1 -1 0\n1 1 -1 0\n2 1 1 0\n3 -1 1 0\n4\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n1\n"
    "0 4 0 1 2 3 0 0 -1 0\n";

class RtResources : public ::testing::Test {
protected:
    void SetUp() override {
        dir_.write("Attributes", "$ 1\n$ 1 1 1 2 2 1 0.1 0.9 0 0 1 0 0 0 0 1\n");
        dir_.write("sq", kFacingSquare);
    }
    // The square seen from (0, 0, -10) at this screendist, on a view of side x side pixels.
    void write_scene(const std::string& screendist, int side) const {
        const std::string last = std::to_string(side - 1);
        dir_.write("s.scn", "$ 0 2 0 0 3 .5 2 1\n$ 0 0 -10 0 0 0\n$ " + screendist +
                                "\n$ 30 30\n$ 1\n$ " + std::to_string(side) + " " +
                                std::to_string(side) + "\n$ 0 0 " + last + " " + last +
                                "\n$ Attributes\n$ 1\n$ 1\n$ 1 1 0 sq 1 0 0 0 0 0 0\n");
    }
    ProgramResult rt(std::vector<std::string> switches = {}) {
        switches.insert(switches.begin(), {"s", "--no-window", "--quiet"});
        return run_program("rt", switches, dir_.path());
    }

    TempDir dir_;
};

// Once "internal error: std::bad_alloc" where memory is short; refused here without allocating.
TEST_F(RtResources, AViewTooBigForTheMemoryIsRefusedWithTheFigures) {
    write_scene("1", 16384);
    const ProgramResult r = rt({"--max-memory", "2", "--output", "s.png"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("rt: the render needs about 4.5 GiB (the film 3.0 GiB, the PNG 1.5 GiB"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("more than the 2.0 GiB available (--max-memory)"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "s.gro"));
}

TEST_F(RtResources, AViewThatFitsStillRenders) {
    write_scene("1", 8);
    const ProgramResult r = rt({"--max-memory", "0.001"});  // 1 MiB
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_.path() / "s.gro"));
}

TEST_F(RtResources, AnOutputFolderThatTakesNoFilesIsRefusedBeforeRendering) {
    if (!fs::is_directory("/proc/self")) {
        GTEST_SKIP() << "no /proc";
    }
    write_scene("1", 8);
    const ProgramResult r = rt({"--output", "/proc/rt-picture.png"});
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_NE(r.err.find("rt: cannot write /proc/rt-picture.png: "), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "s.gro"));
}

TEST_F(RtResources, PolygonsBeforeTheScreenAreWarnedAboutOnce) {
    write_scene("12", 8);  // the square is 10 in front of the eye
    const ProgramResult r = rt();
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string warning =
        "rt: warning: 1 polygon lies between the eye and the screen (screendist 12), where eye "
        "rays, starting on the screen, do not see it: a screendist of 9.9 would show it";
    const std::size_t at = r.err.find(warning);
    EXPECT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(warning, at + 1), std::string::npos) << r.err;
    write_scene("9.9", 8);
    EXPECT_EQ(rt().err.find("between the eye and the screen"), std::string::npos);
}

}  // namespace
}  // namespace rt::test
