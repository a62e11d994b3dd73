// Every placed coordinate, the eye, the look point and the screen distance stay within
// kMaxCoordinate (docs/formats.md, limits), or the reader names the line that broke it.
#include "rt/scene/read/load_scene.h"
#include "rt/scene/read/reader_limits.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

class CoordinateRange : public ::testing::Test {
protected:
    // Header: SEADS (sptncde 8), as in the scene that crashed the grid build.
    static std::string scn(const std::string& entities,
                           const std::string& eye_look = "$ 0 0 -10 0 0 0",
                           const std::string& screen = "$ 1") {
        return "header\n$ 0 2 8 0 3 .5 2 1\n" + eye_look + "\n" + screen +
               "\n$ 40 40\n$ 1\n$ 64 64\n$ 0 0 63 63\n$ Attributes\n" + entities;
    }
    void SetUp() override {
        dir_.write("Attributes", "$ 1\n$ 1 1 1 2 2 0 0.1 0.9 0 0 1 0 0 0 0 1\n");
        dir_.write("sq",
                   "4\n0 -1 0 -1\n1 1 0 -1\n2 1 0 1\n3 -1 0 1\n4\n0 0 1\n1 1 2\n2 2 3\n"
                   "3 3 0\n1\n0 4 0 1 2 3 0 -1 0 0\n");
        dir_.write("far",
                   "4\n0 -1e14 0 -1e14\n1 1e14 0 -1e14\n2 1e14 0 1e14\n3 -1e14 0 1e14\n4\n"
                   "0 0 1\n1 1 2\n2 2 3\n3 3 0\n1\n0 4 0 1 2 3 0 -1 0 0\n");
    }
    std::string error(const std::string& scene_text) {
        return without(
            input_error([&] { load_scene(dir_.write("s.scn", scene_text), {}, diagnostics_); }),
            dir_.path().string() + "/");
    }

    TempDir dir_;
    Diagnostics diagnostics_;
};

TEST_F(CoordinateRange, ATranslationBeyondTheRangeNamesTheScnLine) {
    EXPECT_EQ(error(scn("$ 2\n$ 1\n$ 1 1 0 sq 1 1e308 0 0 0 0 0\n$ 1\n"
                        "$ 2 1 0 sq 1 -1e308 0 0 0 0 0\n")),
              "s.scn:12: expected the translation x (-1e+15 to 1e+15), found '1e308'");
}

TEST_F(CoordinateRange, AVertexPlacedBeyondTheRangeNamesTheVertexLine) {
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 1 0 far 100 0 0 0 0 0 0\n")),
              "far:2: the vertex (-100000000000000, 0, -100000000000000) is placed at (-1e+16, 0, "
              "-1e+16), outside "
              "the coordinate range -1e+15 to 1e+15 by optical surface 'far' (s.scn:12)");
    // A vertex at 1e308 (or 1e20 beside corners at 1) rounds its polygon's area away: the
    // polygon looks degenerate, but the vertex out of range is the mistake, and is reported.
    dir_.write("huge",
               "4\n0 -1 0 -1\n1 1e308 0 -1\n2 1 0 1\n3 -1 0 1\n4\n0 0 1\n1 1 2\n"
               "2 2 3\n3 3 0\n1\n0 4 0 1 2 3 0 -1 0 0\n");
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 1 0 huge 1 0 0 0 0 0 0\n")),
              "huge:3: the vertex (1e+308, 0, -1) is placed at (1e+308, 0, -1), outside the "
              "coordinate range -1e+15 to 1e+15 by optical surface 'huge' (s.scn:12)");
    dir_.write("spike",
               "4\n0 -1 0 -1\n1 1e20 0 -1\n2 1 0 1\n3 -1 0 1\n4\n0 0 1\n1 1 2\n"
               "2 2 3\n3 3 0\n1\n0 4 0 1 2 3 0 -1 0 0\n");
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 1 0 spike 1 0 0 0 0 0 0\n")),
              "spike:3: the vertex (1e+20, 0, -1) is placed at (1e+20, 0, -1), outside the "
              "coordinate range -1e+15 to 1e+15 by optical surface 'spike' (s.scn:12)");
    EXPECT_TRUE(diagnostics_.warnings().empty());
    // A scale that carries an ordinary vertex out of range is caught the same way.
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 1 0 sq 1e300 0 0 0 0 0 0\n")),
              "sq:2: the vertex (-1, 0, -1) is placed at (-1e+300, 0, -1e+300), outside the "
              "coordinate range -1e+15 to 1e+15 by optical surface 'sq' (s.scn:12)");
}

TEST_F(CoordinateRange, TheEdgeOfTheRangeIsAccepted) {
    const Scene scene = load_scene(dir_.write("s.scn", scn("$ 1\n$ 1\n$ 1 1 0 sq 1 999999999999999 "
                                                           "0 0 0 0 0\n")),
                                   {}, diagnostics_);
    EXPECT_EQ(scene.positions.size(), 4u);
}

TEST_F(CoordinateRange, TheEyeLookPointAndScreenDistanceAreLimited) {
    const std::string entities = "$ 1\n$ 1\n$ 1 1 0 sq 1 0 0 0 0 0 0\n";
    EXPECT_EQ(error(scn(entities, "$ 0 0 -1e19 0 0 0")),
              "s.scn:3: expected the eye point's z (-1e+15 to 1e+15), found '-1e19'");
    EXPECT_EQ(error(scn(entities, "$ 0 0 -10 2e15 0 0")),
              "s.scn:3: expected the look point's x (-1e+15 to 1e+15), found '2e15'");
    EXPECT_EQ(error(scn(entities, "$ 0 0 -10 0 0 0", "$ 1e16")),
              "s.scn:4: expected the screen distance (between 1e-05 and 1e+15), found '1e16'");
}

}  // namespace
}  // namespace rt::test
