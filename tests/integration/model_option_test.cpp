// rt --model FILE: a model rendered without a .scn. The scene made around it frames the model on
// a checkerboard under a square light (checked by projecting the model with the camera), the
// picture does not depend on the model's format, and every switch still applies.
#include <algorithm>
#include <filesystem>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/model_scene.h"

#include <gtest/gtest.h>

#include "model_pictures.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

const fs::path bunny_ply = source_dir() / "scenes/models/bunny.ply";

TEST(ModelOption, TheSceneFramesTheModelOnTheFloorUnderTheLight) {
    Diagnostics diagnostics;
    const Scene scene = model_scene(bunny_ply, ReaderDialect{}, diagnostics);
    EXPECT_TRUE(diagnostics.warnings().empty());
    ASSERT_EQ(scene.surfaces.size(), 3u);  // the model, the floor, the light
    ASSERT_EQ(scene.polygons.size(), 3674u + 64u + 1u);
    const Camera camera = scene.view.camera();
    Box3 model;
    double floor_top = -1e300;
    double light_bottom = 1e300;
    std::size_t emitters = 0;
    for (const Polygon& p : scene.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 corner = scene.corner_position(p, k);
            if (p.surface == 0) {
                model.add(corner);
                // Every corner of the model is in front of the eye, inside the picture.
                ASSERT_GT(camera.depth(corner), scene.view.screen_distance);
                double px = 0;
                double py = 0;
                camera.project(corner, px, py);
                EXPECT_GT(px, 0.05 * scene.view.width);
                EXPECT_LT(px, 0.95 * scene.view.width);
                EXPECT_GT(py, 0.05 * scene.view.height);
                EXPECT_LT(py, 0.95 * scene.view.height);
            } else if (p.surface == 1) {
                floor_top = std::max(floor_top, corner.y);
            } else {
                light_bottom = std::min(light_bottom, corner.y);
            }
        }
        emitters += scene.attribute_of(p).is_emissive() ? 1 : 0;
    }
    EXPECT_NEAR(model.largest_extent(), kModelSize, 1e-9);
    EXPECT_GT(model.lo.y, floor_top);  // standing on the floor, not in it
    EXPECT_LT(model.lo.y, floor_top + 0.1);
    EXPECT_GT(light_bottom, model.hi.y);  // the light hangs above it
    EXPECT_EQ(emitters, 1u);
}

class ModelProgram : public ::testing::Test {
protected:
    ProgramResult rt(std::vector<std::string> args) {
        args.emplace_back("--quiet");
        return run_program("rt", args, dir_.path());
    }
    std::string pixels(const std::string& gro) const { return gro_pixels(dir_.path() / gro); }

    TempDir dir_;
};

TEST_F(ModelProgram, RendersTheModelToItsStemWithAPictureThatIsNotBlack) {
    const ProgramResult r = rt({"--model", bunny_ply.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const std::string picture = pixels("bunny.gro");
    ASSERT_EQ(picture.size(), 512u * 400u * 12u);
    EXPECT_NE(picture, std::string(picture.size(), '\0'));
    EXPECT_NE(read_text(dir_.path() / "bunny.gro").find("\nscene --model "), std::string::npos);
}

TEST_F(ModelProgram, ObjAndPlyOfTheBunnyGiveTheSamePictureBitForBit) {
    dir_.write("bunny.obj", bunny_as_obj());
    ASSERT_EQ(rt({"--model", bunny_ply.string(), "-n", "--output", "ply.gro"}).exit_code, 0);
    ASSERT_EQ(rt({"--model", "bunny.obj", "-n", "--output", "obj.gro"}).exit_code, 0);
    EXPECT_FALSE(fs::exists(dir_.path() / "bunny.gro"));  // -n applies
    EXPECT_TRUE(pixels("ply.gro") == pixels("obj.gro"));
}

TEST_F(ModelProgram, EverySwitchStillApplies) {
    ASSERT_EQ(rt({"--model", bunny_ply.string(), "-n", "--output", "octree.gro"}).exit_code, 0);
    // Another intersection method: the same picture (every method answers as brute force does).
    ASSERT_EQ(rt({"--model", bunny_ply.string(), "-n", "--accel", "bvh", "--output", "bvh.gro"})
                  .exit_code,
              0);
    EXPECT_TRUE(pixels("octree.gro") == pixels("bvh.gro"));
    // Switches of the picture change it: no shadow feelers, and smooth shading.
    ASSERT_EQ(
        rt({"--model", bunny_ply.string(), "-n", "-Ds", "-Dd", "--output", "ds.gro"}).exit_code, 0);
    EXPECT_NE(pixels("octree.gro"), pixels("ds.gro"));
    ASSERT_EQ(rt({"--model", bunny_ply.string(), "-n", "-Po", "--output", "po.gro"}).exit_code, 0);
    EXPECT_NE(pixels("octree.gro"), pixels("po.gro"));
    // -p reports the method the model's scene chose and its polygons; --output writes a PPM.
    const ProgramResult p = rt({"--model", bunny_ply.string(), "-n", "-p", "--output", "b.ppm"});
    ASSERT_EQ(p.exit_code, 0);
    EXPECT_NE(p.out.find("octree over 3739 polygons"), std::string::npos) << p.out;
    EXPECT_TRUE(fs::exists(dir_.path() / "b.ppm"));
}

TEST_F(ModelProgram, AMissingOrBrokenModelIsOneLineAndStatus1) {
    const ProgramResult missing = rt({"--model", "none.ply"});
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_EQ(missing.err,
              "--model: cannot open optical surface file 'none.ply' (none.ply): No "
              "such file or directory\n");
    dir_.write("junk.obj", "this is no model\n");
    const ProgramResult junk = rt({"--model", "junk.obj"});
    EXPECT_EQ(junk.exit_code, 1);
    EXPECT_EQ(junk.err, "junk.obj: the model holds no polygons\n");
    // A glTF cut short, and a binary STL cut short: what Assimp did not say, at the line if any.
    dir_.write("cut.gltf", "{\"asset\": {\"version\": \"2.0\"},\n\"scene\": 0\n");
    const ProgramResult gltf = rt({"--model", "cut.gltf"});
    EXPECT_EQ(gltf.exit_code, 1);
    EXPECT_EQ(gltf.err, "cut.gltf:2: expected ',' or '}' in an object, found end of file\n");
    std::string stl(80, ' ');
    stl += std::string("\x0c\0\0\0", 4) + std::string(516, '\0');
    dir_.write("cut.stl", stl);
    const ProgramResult binary = rt({"--model", "cut.stl"});
    EXPECT_EQ(binary.exit_code, 1);
    EXPECT_EQ(binary.err,
              "cut.stl: a binary STL of 12 triangles needs 684 bytes (80-byte header, 4-byte "
              "count, 50 bytes a triangle), found 600\n");
    // Polygons that are all degenerate leave nothing to frame or render either.
    dir_.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    const ProgramResult flat = rt({"--model", "flat.obj"});
    EXPECT_EQ(flat.exit_code, 1);
    EXPECT_NE(flat.err.find("flat.obj: the model holds no polygons that are not degenerate"),
              std::string::npos)
        << flat.err;
}

}  // namespace
}  // namespace rt::test
