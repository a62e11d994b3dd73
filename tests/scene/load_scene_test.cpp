#include "rt/scene/load_scene.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// Copies the manual's scene folder so that tests can add files beside it.
class ManualScene : public ::testing::Test {
protected:
    void SetUp() override {
        fs::copy(scene_data() / "manual", dir_.path(), fs::copy_options::recursive);
    }
    fs::path at(const std::string& name) const { return dir_.path() / name; }
    Scene load(const std::string& name, const ReaderDialect& dialect = {}) {
        return load_scene(at(name), dialect, diagnostics_);
    }
    std::string error(const std::string& name, const ReaderDialect& dialect = {}) {
        return input_error([&] { load(name, dialect); });
    }
    // The message without the temporary folder in front of file names.
    std::string local(std::string message) const {
        const std::string prefix = dir_.path().string() + "/";
        for (std::size_t p; (p = message.find(prefix)) != std::string::npos;) {
            message.erase(p, prefix.size());
        }
        return message;
    }

    TempDir dir_;
    Diagnostics diagnostics_;
};

TEST_F(ManualScene, TheManualsSceneLoadsVerbatim) {
    const Scene scene = load("twocubes.scn");
    EXPECT_EQ(scene.header.center, 0);
    EXPECT_EQ(scene.header.lghtick, 2);
    EXPECT_EQ(scene.header.sptncde, 1);
    EXPECT_EQ(scene.header.octr, 4);
    EXPECT_EQ(scene.header.graphmode, 3);
    EXPECT_EQ(scene.header.normallength, 0.5);
    EXPECT_EQ(scene.header.maxdepth, 2);
    EXPECT_EQ(scene.header.maxdist, 1.0);
    EXPECT_EQ(scene.view.eye, (Vec3{10, 30, -75}));
    EXPECT_EQ(scene.view.look, (Vec3{0, 0, 0}));
    EXPECT_EQ(scene.view.screen_distance, 25.0);
    EXPECT_EQ(scene.view.view_angle_x_degrees, 32.0);
    EXPECT_EQ(scene.view.view_angle_y_degrees, 25.0);
    EXPECT_EQ(scene.view.sample_resolution_x, 1);
    EXPECT_EQ(scene.view.sample_resolution_y, 1);
    EXPECT_EQ(scene.view.width, 512);
    EXPECT_EQ(scene.view.height, 400);
    EXPECT_EQ(scene.view.window, (PixelWindow{0, 0, 511, 399}));
    EXPECT_EQ(scene.attributes.size(), 13u);
    ASSERT_EQ(scene.surfaces.size(), 3u);
    EXPECT_EQ(scene.surfaces[0].file, "cube");
    EXPECT_EQ(scene.surfaces[0].attribute_number, 12);
    EXPECT_EQ(scene.surfaces[2].entity, 3);
    EXPECT_EQ(scene.polygons.size(), 6u + 64u + 1u);
    EXPECT_EQ(scene.polygon_origin.size(), scene.polygons.size());
    EXPECT_EQ(scene.vertex_normals.size(), scene.positions.size());
    // The texture-mapped surface lines at the end are ignored, with one warning.
    ASSERT_EQ(diagnostics_.warnings().size(), 1u);
    EXPECT_EQ(local(diagnostics_.warnings()[0]),
              "twocubes.scn:28: 2 lines after the entities ignored: texture-mapped surfaces are "
              "read only with -V");
}

}  // namespace
}  // namespace rt::test
