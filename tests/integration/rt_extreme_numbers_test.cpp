// Numbers at the edge of what the reader accepts, through the rt program: a scene beyond the
// coordinate or intensity range is refused at the line that caused it (exit 1), never a crash or
// an assertion in an intersection method, and a finished render is never lost to an intensity
// the film cannot hold.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// A unit square in the plane y = 0, facing -y.
const char* const kSquare =
    "4\n0 -1 0 -1\n1 1 0 -1\n2 1 0 1\n3 -1 0 1\n4\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n1\n"
    "0 4 0 1 2 3 0 -1 0 0\n";

class ExtremeNumbers : public ::testing::Test {
protected:
    void SetUp() override {
        dir_.write("Attributes", "$ 1\n$ 1 1 1 2 2 1 0.1 0.9 0 0 1 0 0 0 0 1\n");
        dir_.write("sq", kSquare);
    }
    // header, eye and look, then a 8 x 8 view of the entities.
    std::string scene(const std::string& header, const std::string& eye_look,
                      const std::string& entities) const {
        return "header\n" + header + "\neye look\n" + eye_look +
               "\n$ 1\n$ 40 40\n$ 1\n$ 8 8\n$ 0 0 7 7\n$ Attributes\n" + entities;
    }
    ProgramResult rt(const std::string& scene_text, std::vector<std::string> switches = {}) {
        dir_.write("s.scn", scene_text);
        switches.insert(switches.begin(), {"s", "--no-window", "--quiet"});
        return run_program("rt", switches, dir_.path());
    }

    TempDir dir_;
};

// Once a SIGSEGV in the SEADS grid build: the world's extent overflowed to infinity.
TEST_F(ExtremeNumbers, SeadsSceneFarOutIsRefusedAtItsLine) {
    const ProgramResult r =
        rt(scene("$ 0 2 8 0 3 .5 2 1", "$ 0 0 -10 0 0 0",
                 "$ 2\n$ 1\n$ 1 1 0 sq 1 1e308 0 0 0 0 0\n$ 1\n$ 2 1 0 sq 1 -1e308 0 0 0 0 0\n"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("s.scn:13: expected the translation x (-1e+15 to 1e+15), found '1e308'"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "s.gro"));
}

TEST_F(ExtremeNumbers, VertexScaledOutOfRangeIsRefusedAtItsLine) {
    dir_.write("far",
               "4\n0 -1e14 0 -1e14\n1 1e14 0 -1e14\n2 1e14 0 1e14\n3 -1e14 0 1e14\n4\n"
               "0 0 1\n1 1 2\n2 2 3\n3 3 0\n1\n0 4 0 1 2 3 0 -1 0 0\n");
    const ProgramResult r = rt(
        scene("$ 0 2 8 0 3 .5 2 1", "$ 0 0 -10 0 0 0", "$ 1\n$ 1\n$ 1 1 0 far 100 0 0 0 0 0 0\n"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(
                  "far:2: the vertex (-100000000000000, 0, -100000000000000) is placed at (-1e+16"),
              std::string::npos)
        << r.err;
}

// Once a crash too: a vertex at 1e308 scaled by 2. Its polygon's normal overflows, and the
// polygon, skipped as degenerate, left SEADS an empty grid; now the vertex is refused first.
TEST_F(ExtremeNumbers, VertexAt1e308ScaledByTwoIsRefusedAtItsLine) {
    dir_.write("huge",
               "4\n0 -1 0 -1\n1 1e308 0 -1\n2 1 0 1\n3 -1 0 1\n4\n0 0 1\n1 1 2\n"
               "2 2 3\n3 3 0\n1\n0 4 0 1 2 3 0 -1 0 0\n");
    const ProgramResult r = rt(
        scene("$ 0 2 8 0 3 .5 2 1", "$ 0 0 -10 0 0 0", "$ 1\n$ 1\n$ 1 1 0 huge 2 0 0 0 0 0 0\n"));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("huge:3: the vertex (1e+308, 0, -1) is placed at (inf"), std::string::npos)
        << r.err;
    // A polygon degenerate within the range is still skipped, and SEADS builds an empty grid.
    dir_.write("flat",
               "4\n0 -1 0 -1\n1 0 0 0\n2 1 0 1\n3 2 0 2\n4\n0 0 1\n1 1 2\n"
               "2 2 3\n3 3 0\n1\n0 4 0 1 2 3 0 -1 0 0\n");
    const ProgramResult flat = rt(
        scene("$ 0 2 8 0 3 .5 2 1", "$ 0 0 -10 0 0 0", "$ 1\n$ 1\n$ 1 1 0 flat 2 0 0 0 0 0 0\n"));
    EXPECT_EQ(flat.exit_code, 0) << flat.err;
    EXPECT_NE(flat.err.find("flat:12: polygon 0 is degenerate"), std::string::npos) << flat.err;
}

// Once an assertion in Embree ('ray.valid()'): its float rays start no further out than 1.8e18.
TEST_F(ExtremeNumbers, EyeFarOutIsRefusedBeforeAnyMethodSeesIt) {
    const ProgramResult r = rt(
        scene("$ 0 2 0 0 3 .5 2 1", "$ 0 0 -1e19 0 0 0", "$ 1\n$ 1\n$ 1 1 0 sq 1 0 0 0 -90 0 0\n"),
        {"--accel", "embree"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("s.scn:4: expected the eye point's z (-1e+15 to 1e+15), found '-1e19'"),
              std::string::npos)
        << r.err;
}

// Once accepted with a warning, and then the finished render was lost at the end: the .gro
// writer refused the infinite pixel (exit 4) and no output was written.
TEST_F(ExtremeNumbers, ColourBeyondTheIntensityRangeIsRefusedAtItsLine) {
    dir_.write("Attributes", "$ 1\n$ 1e39 1 1 2 2 1 0.1 0.9 0 0 1 0 0 0 0 1\n");
    const ProgramResult r =
        rt(scene("$ 0 2 0 0 3 .5 2 1", "$ 0 0 -10 0 0 0", "$ 1\n$ 1\n$ 1 1 0 sq 1 0 0 0 -90 0 0\n"),
           {"--output", "s.png"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("Attributes:2: expected the red intensity (-1e+06 to 1e+06), found "
                         "'1e39'"),
              std::string::npos)
        << r.err;
}

// The brightest surfaces the reader accepts, mirrored into each other 64 times: the intensity
// leaves the float range, the samples are counted as black, and every output is still written.
TEST_F(ExtremeNumbers, IntensityBeyondTheFilmIsCountedAndTheRenderKept) {
    dir_.write("Attributes", "$ 1\n$ 1e6 1e6 1e6 2 2 1e6 0 0 1e6 0 1 0 0 0 0 1\n");
    const ProgramResult r =
        rt(scene("$ 0 0 0 0 3 .5 64 1", "$ 0 0 0 0 0 1",
                 "$ 2\n$ 1\n$ 1 1 0 sq 10 0 0 2 90 0 0\n$ 1\n$ 2 1 0 sq 10 0 0 -2 -90 0 0\n"),
           {"--output", "s.png"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("samples had an intensity that is not a finite number within the float "
                         "range; they were counted as black"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(fs::exists(dir_.path() / "s.gro"));
    EXPECT_TRUE(fs::exists(dir_.path() / "s.png"));
}

}  // namespace
}  // namespace rt::test
