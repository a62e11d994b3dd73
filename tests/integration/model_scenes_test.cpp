// Model files (filetype 3) through the rt program: the shipped model scenes, one model as OBJ and
// as PLY giving the same picture bit for bit, and a broken model stopping rt with one line and exit
// status 1.
#include <algorithm>
#include <filesystem>
#include <map>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "model_pictures.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

class ModelScenes : public ::testing::Test {
protected:
    void SetUp() override {
        fs::copy(source_dir() / "scenes", dir_.path() / "scenes", fs::copy_options::recursive);
    }
    ProgramResult rt(const std::vector<std::string>& args) {
        return run_program("rt", args, dir_.path());
    }
    // bunny.scn with its view shrunk to 64 x 50 and the bunny read from `model`, the smooth-shade
    // field added when `smooth` is given ("0" or "1").
    void write_bunny_scene(const std::string& name, const std::string& model,
                           const std::string& smooth = "") {
        std::string scene = read_text(dir_.path() / "scenes/bunny.scn");
        const auto replace = [&](const std::string& from, const std::string& to) {
            const std::size_t at = scene.find(from);
            ASSERT_NE(at, std::string::npos) << from;
            scene.replace(at, from.size(), to);
        };
        replace("$ 512 400", "$ 64 50");
        replace("$ 0 0 511 399", "$ 0 0 63 49");
        replace("3 models/bunny.ply", "3 " + (smooth.empty() ? "" : smooth + " ") + model);
        if (!smooth.empty()) {
            replace("0 0 checker8", "0 0 0 checker8");
            replace("0 square", "0 0 square");
        }
        dir_.write("scenes/" + name, scene);
    }

    TempDir dir_;
};

TEST_F(ModelScenes, TheCornellBoxsMaterialsLandOnItsAttributes) {
    Diagnostics diagnostics;
    const Scene scene =
        load_scene(dir_.path() / "scenes/cornell.scn", ReaderDialect{}, diagnostics);
    std::map<long, int> polygons_per_attribute;
    for (const Polygon& p : scene.polygons) {
        ++polygons_per_attribute[scene.attribute_of(p).index];
    }
    // White: floor (3 faces, two under the blocks), ceiling, back wall, two blocks of 5 faces.
    // Red and green walls, and the square light; no blue (the model's front wall is left out).
    EXPECT_EQ(polygons_per_attribute, (std::map<long, int>{{0, 15}, {1, 1}, {2, 1}, {4, 1}}));
    // Mirrored in z: the red wall is at x = 55, on the left of a camera looking along -z.
    for (const Polygon& p : scene.polygons) {
        if (scene.attribute_of(p).index == 1) {
            EXPECT_GT(scene.corner_position(p, 0).x, 54.0);
            EXPECT_LT(p.normal.x, -0.99);  // facing into the box
        }
    }
    EXPECT_GT(scene.view.eye.z, 0.0);
}

TEST_F(ModelScenes, ObjAndPlyOfTheBunnyGiveTheSamePictureBitForBit) {
    dir_.write("scenes/models/bunny.obj", bunny_as_obj());
    for (const std::string smooth : {"", "1"}) {
        SCOPED_TRACE("smooth-shade field '" + smooth + "'");
        write_bunny_scene("from_ply.scn", "models/bunny.ply", smooth);
        write_bunny_scene("from_obj.scn", "models/bunny.obj", smooth);
        const std::vector<std::string> po =
            smooth.empty() ? std::vector<std::string>{} : std::vector<std::string>{"-Po"};
        std::vector<std::string> ply_args = {"scenes/from_ply", "--quiet"};
        std::vector<std::string> obj_args = {"scenes/from_obj", "--quiet"};
        ply_args.insert(ply_args.end(), po.begin(), po.end());
        obj_args.insert(obj_args.end(), po.begin(), po.end());
        ASSERT_EQ(rt(ply_args).exit_code, 0);
        ASSERT_EQ(rt(obj_args).exit_code, 0);
        const std::string ply = gro_pixels(dir_.path() / "from_ply.gro");
        const std::string obj = gro_pixels(dir_.path() / "from_obj.gro");
        ASSERT_EQ(ply.size(), 64u * 50u * 12u);
        EXPECT_TRUE(ply == obj);
        EXPECT_NE(ply, std::string(ply.size(), '\0')) << "a black picture would prove nothing";
    }
}

TEST_F(ModelScenes, SmoothShadingChangesTheBunny) {
    write_bunny_scene("flat.scn", "models/bunny.ply", "0");
    write_bunny_scene("smooth.scn", "models/bunny.ply", "1");
    ASSERT_EQ(rt({"scenes/flat", "--quiet", "-Po"}).exit_code, 0);
    ASSERT_EQ(rt({"scenes/smooth", "--quiet", "-Po"}).exit_code, 0);
    EXPECT_NE(gro_pixels(dir_.path() / "flat.gro"), gro_pixels(dir_.path() / "smooth.gro"));
}

TEST_F(ModelScenes, ABrokenModelStopsRtWithOneLineAndStatus1) {
    dir_.write("scenes/models/bunny.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n");
    write_bunny_scene("broken.scn", "models/bunny.obj");
    const ProgramResult r = rt({"scenes/broken"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "scenes/models/bunny.obj: cannot read the model: OBJ: vertex index out of "
              "range\n");
    EXPECT_FALSE(fs::exists(dir_.path() / "broken.gro"));
    dir_.write("scenes/models/bunny.ply",
               "ply\nformat ascii 1.0\nelement vertex 99999\n"
               "property float x\nend_header\n1\n");
    write_bunny_scene("broken.scn", "models/bunny.ply");
    const ProgramResult h = rt({"scenes/broken"});
    EXPECT_EQ(h.exit_code, 1);
    EXPECT_NE(h.err.find("scenes/models/bunny.ply:3: the header promises 99999 vertex elements"),
              std::string::npos)
        << h.err;
}

}  // namespace
}  // namespace rt::test
