// Filetype 3 in a scene: a model file is placed, attributed and smooth-shaded like a polygon file,
// and its own normals feed smooth shading.
#include <cmath>
#include <numbers>

#include "rt/geometry/normals.h"
#include "rt/scene/crease_normals.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "model_files.h"
#include "reader_test_support.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// A scene of one model surface: "$ 1 ATTRIBUTE 3 [SMOOTH] FILE PLACEMENT".
class ModelScene : public ::testing::Test {
protected:
    ModelScene() {
        dir_.write("Attributes",
                   "$ 6\n"
                   "$ 0.9 0.9 0.9 2 2 0 0.1 0.9 0 0 1 60 4 60 4 0\n"
                   "$ 0.9 0.1 0.1 2 2 0 0.1 0.9 0 0 1 60 4 60 4 1\n"
                   "$ 0.1 0.9 0.1 2 2 0 0.1 0.9 0 0 1 60 4 60 4 2\n"
                   "$ 0.1 0.1 0.9 2 2 0 0.1 0.9 0 0 1 60 4 60 4 3\n"
                   "$ 1 1 1 2 2 1 0 0 0 0 1 60 4 60 4 4\n"
                   "$ 0.5 0.5 0.5 2 2 0 0.1 0.9 0 0 1 60 4 60 4 5\n");
    }
    Scene load(const std::string& surface_line, const ReaderDialect& dialect = {}) {
        dir_.write("m.scn",
                   "$ 0 2 0 0 0 1 2 1\n$ 0 0 -10 0 0 0\n$ 1\n$ 40 40\n$ 1\n$ 8 8\n"
                   "$ 0 0 7 7\n$ Attributes\n$ 1\n$ 1\n$ " +
                       surface_line + "\n");
        return load_scene(dir_.path() / "m.scn", dialect, diagnostics_);
    }
    std::string error(const std::string& surface_line, const ReaderDialect& dialect = {}) {
        return without(input_error([&] { load(surface_line, dialect); }),
                       dir_.path().string() + "/");
    }
    static ReaderDialect smooth_field() {
        ReaderDialect d;
        d.smooth_shade_field = true;
        return d;
    }

    TempDir dir_;
    Diagnostics diagnostics_;
};

// One square in z = 0 whose corner (1, 1, 0) has a leaning normal; the others point along +z.
const std::string leaning_square =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0.6 0.8\n"
    "f 1//1 2//1 3//2 4//1\n";

TEST_F(ModelScene, ASmoothModelShadesWithTheFilesNormalsPlacedWithIt) {
    dir_.write("sq.obj", leaning_square);
    // Turned 90 degrees about x: +y goes to +z, +z to -y.
    const Scene scene = load("1 0 3 1 sq.obj 2 5 0 0 90 0 0", smooth_field());
    ASSERT_EQ(scene.polygons.size(), 1u);
    EXPECT_TRUE(scene.polygons[0].smooth);
    ASSERT_EQ(scene.model_normals.size(), 4u);
    ASSERT_EQ(scene.corner_normals.size(), 4u);
    const Vec3 corner = scene.corner_position(scene.polygons[0], 2);
    EXPECT_EQ(corner, (Vec3{7, 0, 2}));
    const Vec3 n = interpolated_normal(scene.polygon_view(0), scene.normals_of(0), corner);
    EXPECT_NEAR(n.x, 0.0, 1e-6);
    EXPECT_NEAR(n.y, -0.8, 1e-6);
    EXPECT_NEAR(n.z, 0.6, 1e-6);
    // The plane's own normal follows the file's normals: -y after the turn.
    EXPECT_EQ(scene.polygons[0].normal, (Vec3{0, -1, 0}));
}

TEST_F(ModelScene, WithoutTheSmoothFieldTheFilesNormalsAreNotUsed) {
    dir_.write("sq.obj", leaning_square);
    const Scene scene = load("1 0 3 sq.obj 1 0 0 0 0 0 0");
    EXPECT_FALSE(scene.polygons[0].smooth);
    EXPECT_TRUE(scene.model_normals.empty());
    EXPECT_TRUE(scene.corner_normals.empty());
}

TEST_F(ModelScene, WithoutFileNormalsOurVertexNormalsAreUsed) {
    dir_.write("cube.obj",
               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n"
               "v 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\n"
               "f 2 3 7 6\n");
    const Scene scene = load("1 0 3 1 cube.obj 1 0 0 0 0 0 0", smooth_field());
    EXPECT_TRUE(scene.corner_normals.empty());
    ASSERT_EQ(scene.positions.size(), 8u);
    // Each vertex normal is the diagonal: the three faces there weigh alike.
    const double d = 1.0 / std::sqrt(3.0);
    const Vec3 n = scene.vertex_normals[scene.corners[scene.polygons[1].first_corner + 2]];
    EXPECT_NEAR(n.x, d, 1e-12);
    EXPECT_NEAR(n.y, d, 1e-12);
    EXPECT_NEAR(n.z, d, 1e-12);
}

TEST_F(ModelScene, CreaseAngleKeepsTheFilesNormalsAndSharpensTheRest) {
    // The leaning square, and a cube without normals beside it.
    dir_.write("two.obj", leaning_square +
                              "v 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\nv 5 0 1\nv 6 0 1\nv 6 1 1\n"
                              "v 5 1 1\nf 5 8 7 6\nf 9 10 11 12\nf 5 6 10 9\nf 8 12 11 7\n"
                              "f 5 9 12 8\nf 6 7 11 10\n");
    Scene scene = load("1 0 3 1 two.obj 1 0 0 0 0 0 0", smooth_field());
    ASSERT_EQ(scene.polygons.size(), 7u);
    compute_crease_normals(scene, std::numbers::pi / 4);
    EXPECT_NEAR(scene.corner_normals[2].y, 0.6, 1e-6);  // the file's leaning normal stays
    // The cube's corners take their own face's normal: its edges are sharper than 45 degrees.
    for (std::uint32_t id = 1; id < 7; ++id) {
        const Polygon& p = scene.polygons[id];
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            EXPECT_EQ(scene.corner_normals[p.first_corner + k], p.normal);
        }
    }
}

TEST_F(ModelScene, MaterialsOffsetTheSurfacesAttribute) {
    dir_.write("m.mtl", "newmtl a\nKd 1 1 1\nnewmtl b\nKd 1 0 0\nnewmtl c\nKd 0 1 0\n");
    dir_.write("m.obj",
               "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
               "usemtl c\nf 1 2 3\nusemtl a\nf 1 3 4\n");
    const Scene scene = load("1 3 3 m.obj 1 0 0 0 0 0 0");
    ASSERT_EQ(scene.polygons.size(), 2u);
    EXPECT_EQ(scene.attributes[scene.polygons[0].attribute].index, 5);
    EXPECT_EQ(scene.attributes[scene.polygons[1].attribute].index, 3);
    // Out of range, as for filetype 0: at the polygon when the offset is not 0 ...
    EXPECT_EQ(error("1 4 3 m.obj 1 0 0 0 0 0 0"),
              "m.obj: polygon 0 uses attribute 6 (attribute 4 of the optical surface + offset "
              "2), which is not defined");
    // ... and at the .scn line when it is.
    dir_.write("n.obj", quad_pentagon_obj);
    EXPECT_EQ(error("1 9 3 n.obj 1 0 0 0 0 0 0"),
              "m.scn:11: optical surface 'n.obj' uses attribute 9, which is not defined");
}

TEST_F(ModelScene, ObjAndPlyOfOneModelMakeTheSameScene) {
    dir_.write("m.obj", quad_pentagon_obj);
    dir_.write("m.ply", quad_pentagon_ply);
    const Scene obj = load("1 2 3 m.obj 3 1 2 3 10 20 30");
    const Scene ply = load("1 2 3 m.ply 3 1 2 3 10 20 30");
    EXPECT_EQ(obj.positions, ply.positions);
    EXPECT_EQ(obj.corners, ply.corners);
    ASSERT_EQ(obj.polygons.size(), ply.polygons.size());
    for (std::size_t i = 0; i < obj.polygons.size(); ++i) {
        EXPECT_EQ(obj.polygons[i].normal, ply.polygons[i].normal);
        EXPECT_EQ(obj.polygons[i].attribute, ply.polygons[i].attribute);
    }
}

TEST_F(ModelScene, ManyDegenerateFacesAreNamedTenAndCounted) {
    std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 0 0\nf 1 2 3\n";
    for (int i = 0; i < 1000; ++i) {
        obj += "f 1 2 4\n";
    }
    dir_.write("m.obj", obj);
    const Scene scene = load("1 0 3 m.obj 1 0 0 0 0 0 0");
    EXPECT_EQ(scene.polygons.size(), 1u);
    std::vector<std::string> degenerate;
    for (const std::string& w : diagnostics_.warnings()) {
        if (w.find("degenerate") != std::string::npos) {
            degenerate.push_back(without(w, dir_.path().string() + "/"));
        }
    }
    ASSERT_EQ(degenerate.size(), 11u);
    EXPECT_EQ(degenerate[0], "m.obj: polygon 1 is degenerate (zero area); skipped");
    EXPECT_EQ(degenerate[10],
              "990 more degenerate polygons in m.obj skipped (the first 10 are named above)");
}

TEST_F(ModelScene, ADegenerateFaceIsSkippedWithAWarningNamingTheFile) {
    dir_.write("m.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n");
    const Scene scene = load("1 0 3 m.obj 1 0 0 0 0 0 0");
    EXPECT_EQ(scene.polygons.size(), 1u);
    bool warned = false;
    for (const std::string& w : diagnostics_.warnings()) {
        warned |= without(w, dir_.path().string() + "/") ==
                  "m.obj: polygon 1 is degenerate (zero area); skipped";
    }
    EXPECT_TRUE(warned);
}

TEST_F(ModelScene, TheFiletypeAndTheFormatMustAgree) {
    dir_.write("cube", read_text(scene_data() / "manual/cube"));
    EXPECT_EQ(error("1 0 3 cube 1 0 0 0 0 0 0"),
              "m.scn:11: optical surface file 'cube' has filetype 3 (a model file), but a name "
              "without an extension is no model format Assimp reads (.obj, .ply, .stl, .gltf, "
              ".glb, .off, ...)");
}

}  // namespace
}  // namespace rt::test
