// rt's runs that trace no ray, as a user meets them: -w writes the wireframe where the picture
// would go (with -oo the octree's boxes), and -doi answers commands read on standard input.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "rt/image/gro_format.h"
#include "rt/image/png_format.h"
#include "rt/wireframe/wireframe.h"

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

bool is(const Rgb& v, const Rgb& colour) {
    return v.r == colour.r && v.g == colour.g && v.b == colour.b;
}

// How many pixels of the film are each colour of the wireframe, and how many are anything else.
struct Census {
    int black = 0;
    int edges = 0;
    int normals = 0;
    int boxes = 0;
    int other = 0;
};

Census census(const Film& film) {
    Census c;
    const PixelRect& w = film.window();
    for (int y = w.top; y <= w.bottom; ++y) {
        for (int x = w.left; x <= w.right; ++x) {
            const Rgb v = film.pixel(x, y);
            if (is(v, Rgb{})) {
                ++c.black;
            } else if (is(v, kWireEdgeColour)) {
                ++c.edges;
            } else if (is(v, kWireNormalColour)) {
                ++c.normals;
            } else if (is(v, kWireOctreeColour)) {
                ++c.boxes;
            } else {
                ++c.other;
            }
        }
    }
    return c;
}

class Inspection : public ::testing::Test {
protected:
    ProgramResult rt(const std::vector<std::string>& args, const fs::path& input = "/dev/null") {
        std::vector<std::string> all = {(source_dir() / "scenes" / "twocubes").string()};
        all.insert(all.end(), args.begin(), args.end());
        return run_program("rt", all, dir_.path(), input);
    }
    fs::path at(const std::string& name) const { return dir_.path() / name; }

    TempDir dir_;
};

TEST_F(Inspection, DashWWritesTheWireframeAsThePicture) {
    const ProgramResult r = rt({"-w", "--output", "w.png"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Film film = read_gro(at("twocubes.gro"));
    EXPECT_TRUE(film.complete());
    EXPECT_EQ(film.provenance.switches, "-w");
    const Census c = census(film);
    // twocubes: a cube, an 8 x 8 checkerboard and a light, with normals 0.5 long.
    EXPECT_GT(c.edges, 1000);
    EXPECT_GT(c.normals, 50);
    EXPECT_EQ(c.boxes, 0);
    EXPECT_EQ(c.other, 0);
    EXPECT_GT(c.black, 400 * 512 * 9 / 10);
    const Image8 png = read_png(at("w.png"));
    EXPECT_EQ(png.width, 512);
    EXPECT_EQ(png.height, 400);
}

TEST_F(Inspection, DashOoAddsTheOctreesBoxesWhateverTheMethod) {
    ASSERT_EQ(rt({"-w", "-n", "--output", "plain.gro"}).exit_code, 0);
    const ProgramResult boxed = rt({"-w", "-oo", "-n", "--output", "boxed.gro"});
    ASSERT_EQ(boxed.exit_code, 0) << boxed.err;
    EXPECT_FALSE(fs::exists(at("twocubes.gro")));  // -n
    const Census plain = census(read_gro(at("plain.gro")));
    const Census with_boxes = census(read_gro(at("boxed.gro")));
    EXPECT_GT(with_boxes.boxes, 1000);
    EXPECT_EQ(with_boxes.edges, plain.edges);  // the polygons' edges are drawn over the boxes
    // The header names the octree; with another method the octree is built for the drawing.
    EXPECT_EQ(boxed.err.find("-oo: the intersection method"), std::string::npos) << boxed.err;
    const ProgramResult brute =
        rt({"-w", "-oo", "-n", "--output", "brute.gro", "--accel", "brute"});
    ASSERT_EQ(brute.exit_code, 0) << brute.err;
    EXPECT_NE(brute.err.find("rt: -oo: the intersection method is brute; -oo shows the octree "
                             "--accel octree would build (depth 4)"),
              std::string::npos)
        << brute.err;
    EXPECT_EQ(census(read_gro(at("brute.gro"))).boxes, with_boxes.boxes);
}

TEST_F(Inspection, DashWHonoursTheWindowAndDashL) {
    ASSERT_EQ(rt({"-w", "-n", "--output", "whole.gro"}).exit_code, 0);
    ASSERT_EQ(rt({"-w", "-n", "-L150", "--output", "cut.gro"}).exit_code, 0);
    const Film whole = read_gro(at("whole.gro"));
    const Film cut = read_gro(at("cut.gro"));
    EXPECT_EQ(cut.window(), (PixelRect{0, 0, 511, 150}));
    for (int y = 0; y <= 150; ++y) {
        for (int x = 0; x <= 511; ++x) {
            ASSERT_TRUE(is(cut.pixel(x, y), whole.pixel(x, y))) << x << ", " << y;
        }
    }
}

TEST_F(Inspection, DashOoWithoutDashWSaysThePictureIsRayTracedAsUsual) {
    const ProgramResult r = rt({"-oo", "-n", "-L5"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("rt: -oo draws the octree's boxes on the wireframe, which only -w "
                         "writes; the picture is ray traced as usual"),
              std::string::npos)
        << r.err;
}

TEST_F(Inspection, DashDoiAnswersCommandsFromStandardInputAndRendersNothing) {
    const fs::path script = dir_.write("script.txt",
                                       "# walk to a leaf and back\n"
                                       "child 0\n"
                                       "up\n"
                                       "find 2 0 2\n"
                                       "pixel 256 200\n"
                                       "nonsense\n");
    const ProgramResult r = rt({"-doi"}, script);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> lines = lines_of(r.out);
    ASSERT_GE(lines.size(), 8U) << r.out;
    EXPECT_EQ(lines[0].rfind("octree: depth 4, ", 0), 0U) << lines[0];
    EXPECT_EQ(lines[2].rfind("node 1, path 0 (level 1): ", 0), 0U) << lines[2];  // no prompt
    EXPECT_EQ(lines[3].rfind("node 0, the root", 0), 0U) << lines[3];
    EXPECT_EQ(lines[4], "(2, 0, 2) is in lattice cell (7, 1, 7)");
    // The eye ray through the middle of the picture meets the cube (polygons 0 to 5).
    const auto hit = std::find_if(lines.begin(), lines.end(),
                                  [](const std::string& l) { return l.rfind("hit: ", 0) == 0; });
    ASSERT_NE(hit, lines.end()) << r.out;
    EXPECT_NE(hit->find("scenes/cube:"), std::string::npos) << *hit;
    EXPECT_EQ(lines.back(), "error: unknown command 'nonsense'; 'help' lists the commands");
    EXPECT_NE(r.err.find("rt: -doi: session over (1 command failed); no picture is rendered"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(at("twocubes.gro")));
}

}  // namespace
}  // namespace rt::test
