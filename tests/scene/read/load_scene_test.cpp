#include "rt/scene/read/load_scene.h"

#include <algorithm>

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
    std::string local(const std::string& message) const {
        return without(message, dir_.path().string() + "/");
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
    EXPECT_EQ(scene.view.window, (PixelRect{0, 0, 511, 399}));
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

TEST_F(ManualScene, SurfacesArePlacedAndNormalsPointOutward) {
    const Scene scene = load("twocubes.scn");
    // Vertices are shared within a surface: 8 for the cube, 81 for the checkerboard, 4 for the
    // square.
    EXPECT_EQ(scene.positions.size(), 8u + 81u + 4u);
    EXPECT_EQ(scene.corners.size(), 6u * 4 + 64u * 4 + 4u);
    const Vec3 centre{2, 0, 2};  // the cube's translation
    for (std::uint32_t i = 0; i < 6; ++i) {
        const Polygon& p = scene.polygons[i];
        EXPECT_EQ(p.attribute, 12u);  // attribute number 12 is the 13th line
        EXPECT_EQ(p.surface, 0u);
        Vec3 middle;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            middle += scene.corner_position(p, k) * 0.25;
        }
        EXPECT_NEAR(dot(p.normal, normalize(middle - centre)), 1.0, 1e-12) << "face " << i;
        EXPECT_FALSE(p.smooth);
        EXPECT_EQ(p.shape, Polygon::kNoShape);
    }
    // The checkerboard alternates attributes 0 and 1 through the polygons' offsets.
    EXPECT_EQ(scene.polygons[6].attribute, 0u);
    EXPECT_EQ(scene.polygons[7].attribute, 1u);
    EXPECT_EQ(scene.polygons[6].normal, (Vec3{0, 1, 0}));
    EXPECT_EQ(scene.positions[8], (Vec3{-8, -3, -8}));  // (-2, 0, -2) * 4 + (0, -3, 0)
    // The light faces down, tilted by its rotations.
    const Polygon& light = scene.polygons.back();
    EXPECT_LT(light.normal.y, -0.9);
    EXPECT_TRUE(scene.attribute_of(light).is_emissive());
    EXPECT_EQ(scene.origin_of(static_cast<std::uint32_t>(scene.polygons.size() - 1)).to_string(),
              at("square").string() + ":12");
    EXPECT_EQ(scene.source_files.size(), 5u);  // the .scn, Attributes, cube, checker8, square
}

// A scene in a temporary folder: the manual's view with the given entities and attributes.
class SmallScene : public ::testing::Test {
protected:
    static std::string scn(const std::string& entities,
                           const std::string& attributes = "$ Attributes",
                           const std::string& header = "$ 0 2 0 0 0 .5 2 1") {
        return "header\n" + header +
               "\n$ 0 0 -10 0 0 0\n$ 1\n$ 40 40\n$ 1\n$ 64 64\n$ 0 0 63 63\n" + attributes + "\n" +
               entities;
    }
    void SetUp() override {
        dir_.write(
            "Attributes",
            "$ 3\n$ 1 1 1 2 2 0 0.1 0.9 0 0 1 0 0 0 0 1\n$ 1 0 0 2 2 0 0.1 0.9 0 0 1 0 0 0 0 "
            "2\n$ 1 1 1 2 2 1 0 0 0 0 1 0 0 0 0 3\n");
        dir_.write("tri", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1 0 3 0 1 2 0 0 1 0");
    }
    Scene load(const std::string& scene_text, const ReaderDialect& dialect = {}) {
        return load_scene(dir_.write("s.scn", scene_text), dialect, diagnostics_);
    }
    std::string error(const std::string& scene_text, const ReaderDialect& dialect = {}) {
        return without(input_error([&] { load(scene_text, dialect); }), dir_.path().string() + "/");
    }

    TempDir dir_;
    Diagnostics diagnostics_;
};

TEST_F(SmallScene, AVertexThroughScaleRotateTranslate) {
    // Vertex (1, 0, 0) of tri, scaled by 2, rotated 90 about y (to (0, 0, -2)), then about z
    // (unchanged), then moved by (10, 20, 30).
    const Scene scene = load(scn("$ 1\n$ 1\n$ 1 1 0 tri 2 10 20 30 0 90 90\n"));
    ASSERT_EQ(scene.positions.size(), 3u);
    EXPECT_EQ(scene.positions[1], (Vec3{10, 20, 28}));
    EXPECT_EQ(scene.positions[0], (Vec3{10, 20, 30}));
    // (0, 1, 0) * 2: about y unchanged, about z by 90 turns +y to -x.
    EXPECT_EQ(scene.positions[2], (Vec3{8, 20, 30}));
    // The file's outward normal (0, 0, 1) turned the same way: +x about y, then +y about z.
    EXPECT_EQ(scene.polygons[0].normal, (Vec3{0, 1, 0}));
}

TEST_F(SmallScene, ANegativeScaleKeepsNormalsOutward) {
    const Scene scene = load(scn("$ 1\n$ 1\n$ 1 1 0 tri -1 0 0 0 0 0 0\n"));
    EXPECT_EQ(scene.positions[1], (Vec3{-1, 0, 0}));
    EXPECT_EQ(scene.polygons[0].normal, (Vec3{0, 0, -1}));
}

TEST_F(SmallScene, OutwardDirectionPicksTheSide) {
    // The loop runs counter-clockwise about +z; the file says outward is -z.
    dir_.write("down", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1 0 3 0 1 2 0.3 0 -1 0");
    // No outward direction (zero): the loop's own right-hand rule.
    dir_.write("none", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1 0 3 0 1 2 0 0 0 0");
    // In the plane of the polygon: no help either.
    dir_.write("flat", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1 0 3 0 1 2 1 1 0 0");
    const Scene scene =
        load(scn("$ 3\n$ 1\n$ 1 1 0 down 1 0 0 0 0 0 0\n$ 1\n$ 1 1 0 none 1 0 0 0 0 0 "
                 "0\n$ 1\n$ 1 1 0 flat 1 0 0 0 0 0 0\n"));
    EXPECT_EQ(scene.polygons[0].normal, (Vec3{0, 0, -1}));
    EXPECT_EQ(scene.polygons[1].normal, (Vec3{0, 0, 1}));
    EXPECT_EQ(scene.polygons[2].normal, (Vec3{0, 0, 1}));
}

TEST_F(SmallScene, AutoCenteringMovesTheLookPoint) {
    const Scene scene =
        load(scn("$ 1\n$ 1\n$ 1 1 0 tri 4 10 0 0 0 0 0\n", "$ Attributes", "$ 1 2 0 0 0 .5 2 1"));
    EXPECT_EQ(scene.view.look, (Vec3{12, 2, 0}));
    EXPECT_EQ(diagnostics_.notes(),
              (std::vector<std::string>{"auto-centering: look point set to (12, 2, 0)"}));
}

TEST_F(SmallScene, AutoCenteringOntoTheEyeIsAnError) {
    dir_.write("sq",
               "4 0 -1 0 -1 1 1 0 -1 2 1 0 1 3 -1 0 1 4 0 0 1 1 1 2 2 2 3 3 3 0 1 "
               "0 4 0 1 2 3 0 -1 0 0");
    EXPECT_EQ(
        error(scn("$ 1\n$ 1\n$ 1 1 0 sq 1 0 0 -10 0 0 0\n", "$ Attributes", "$ 1 2 0 0 0 .5 2 1")),
        "s.scn:3: the eye point and the look point are the same (0, 0, -10)");
}

TEST_F(SmallScene, EmptySceneIsAWarning) {
    const Scene scene = load(scn("$ 0\n"));
    EXPECT_TRUE(scene.polygons.empty());
    ASSERT_EQ(diagnostics_.warnings().size(), 1u);
    EXPECT_EQ(diagnostics_.warnings()[0],
              (dir_.path() / "s.scn").string() + ": the scene has no polygons");
}

TEST_F(SmallScene, DegeneratePolygonsAreWarnedAndSkipped) {
    dir_.write("bad",
               "4 0 0 0 0 1 1 0 0 2 2 0 0 3 0 1 0\n"
               "5 0 0 1 1 1 2 2 2 0 3 1 3 4 3 0\n"
               "3\n0 3 0 1 2 0 0 1 0\n"
               "1 2 0 3 0 0 1 0\n"
               "2 3 0 4 3 0 0 1 0\n");
    const Scene scene = load(scn("$ 1\n$ 1\n$ 1 1 0 bad 1 0 0 0 0 0 0\n"));
    EXPECT_EQ(scene.polygons.size(), 1u);
    EXPECT_EQ(scene.positions.size(), 3u);  // vertex 2 is used only by the skipped polygon
    const std::string bad = (dir_.path() / "bad").string();
    EXPECT_EQ(
        diagnostics_.warnings(),
        (std::vector<std::string>{bad + ":5: polygon 1 is degenerate (fewer than 3 edges); skipped",
                                  bad + ":4: polygon 0 is degenerate (zero area); skipped"}));
}

TEST_F(SmallScene, SmoothShadeFieldGivesVertexNormals) {
    ReaderDialect po;
    po.smooth_shade_field = true;
    // Two triangles folded along the x axis: the shared corners average both normals.
    dir_.write("fold",
               "4 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1\n5 0 0 1 1 1 2 2 2 0 3 1 3 4 3 0\n"
               "2 0 3 0 1 2 0 0 1 0 1 3 0 3 4 0 -1 0 0\n");
    const Scene scene =
        load(scn("$ 1\n$ 2\n$ 1 1 0 1 fold 1 0 0 0 0 0 0\n$ 2 1 0 0 tri 1 5 5 5 0 0 0\n"), po);
    ASSERT_EQ(scene.polygons.size(), 3u);
    EXPECT_TRUE(scene.polygons[0].smooth);
    EXPECT_FALSE(scene.polygons[2].smooth);
    ASSERT_EQ(scene.vertex_normals.size(), 7u);
    const double h = std::sqrt(0.5);
    EXPECT_NEAR(scene.vertex_normals[0].y, -h, 1e-12);
    EXPECT_NEAR(scene.vertex_normals[0].z, h, 1e-12);
    EXPECT_EQ(scene.vertex_normals[2], (Vec3{0, 0, 1}));  // only the flat triangle uses it
    EXPECT_EQ(scene.vertex_normals[6], Vec3{});           // not smooth
}

TEST_F(SmallScene, MarksAndShapesWithM) {
    ReaderDialect m;
    m.marks = true;
    dir_.write("shapes", "$ 2\n$ 0 0 0 1 0 0 0 a sphere\n$ 0 0 0 0.5 0 1 0 a cylinder\n");
    dir_.write("marked",
               "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0\n"
               "3\n0 3 0 1 2 0 0 1 0 2 0\n1 3 0 1 2 0 0 1 0 3 1\n2 3 0 1 2 0 0 1 0 1 7\n");
    for (const std::string line : {"$@shapes", "$ @shapes"}) {
        const Scene scene = load(
            scn(line + "\n$ 1\n$ 2\n$ 1 1 0 marked 2 1 0 0 0 0 0\n$ 1 1 0 marked 1 0 0 0 0 0 0\n"),
            m);
        ASSERT_EQ(scene.polygons.size(), 6u);
        EXPECT_EQ(scene.polygons[0].mark, PolygonMark::Sphere);
        EXPECT_EQ(scene.polygons[1].mark, PolygonMark::Cylinder);
        EXPECT_EQ(scene.polygons[2].mark, PolygonMark::InterpolatesNormals);
        EXPECT_TRUE(scene.polygons[2].smooth);
        EXPECT_EQ(scene.polygons[2].shape, Polygon::kNoShape);
        // Each surface has its own world-space copy of the shapes it uses.
        ASSERT_EQ(scene.shapes.size(), 4u);
        const Shape& sphere = scene.shapes[static_cast<std::size_t>(scene.polygons[0].shape)];
        EXPECT_EQ(sphere.index, 0);
        EXPECT_EQ(sphere.first, (Vec3{1, 0, 0}));
        EXPECT_EQ(sphere.radius_or_angle, 2.0);
        const Shape& tube = scene.shapes[static_cast<std::size_t>(scene.polygons[1].shape)];
        EXPECT_EQ(tube.index, 1);
        EXPECT_EQ(tube.second, (Vec3{1, 2, 0}));
        EXPECT_EQ(scene.shapes[static_cast<std::size_t>(scene.polygons[3].shape)].radius_or_angle,
                  1.0);
    }
}

TEST_F(SmallScene, FiletypesOneAndTwoInOneScene) {
    fs::copy(scene_data() / "phigscube", dir_.path() / "phigscube");
    fs::copy(scene_data() / "manual/prinzcube", dir_.path() / "prinzcube");
    const Scene scene =
        load(scn("$ 2\n$ 1\n$ 1 1 1 phigscube 1 0 0 5 0 0 0\n"
                 "$ 1\n$ 2 2 2 prinzcube 1 3 0 5 0 0 0\n"));
    ASSERT_EQ(scene.polygons.size(), 6u + 12u);
    EXPECT_EQ(scene.polygons[2].attribute, 1u);  // attribute 1 + offset 1 is the second line
    EXPECT_EQ(scene.positions.size(), 24u + 8u);
    for (std::uint32_t i = 0; i < scene.polygons.size(); ++i) {
        const Polygon& p = scene.polygons[i];
        const Vec3 centre = i < 6 ? Vec3{0, 0, 5} : Vec3{3, 0, 5};
        EXPECT_GT(dot(p.normal, scene.corner_position(p, 0) - centre), 0) << i;
    }
}

TEST_F(SmallScene, OldFormatInlineAttributesWithoutPowerFields) {
    ReaderDialect of;
    of.attributes_inline = true;
    of.no_power_fields = true;
    of.rgb_refraction = true;
    const Scene scene =
        load(scn("$ 1\n$ 1\n$ 1 5 0 tri 1 0 0 0 0 0 0\n",
                 "attributes\n$ 1\n$ 0.5 0.5 0.5 0 0.1 0.9 0 0 1.5 1.6 1.7 60 4 60 4 5"),
             of);
    ASSERT_EQ(scene.attributes.size(), 1u);
    EXPECT_EQ(scene.attributes[0].specular_exponent, 2.0);
    EXPECT_EQ(scene.attributes[0].refraction_index, (Rgb{1.5, 1.6, 1.7}));
    EXPECT_EQ(scene.polygons.at(0).attribute, 0u);
    EXPECT_EQ(scene.source_files.size(), 2u);  // the .scn and tri: no Attributes file
}

TEST_F(SmallScene, FilesNamedByTheSceneAreResolvedBesideIt) {
    fs::create_directories(dir_.path() / "sub");
    dir_.write("sub/Attributes", read_text(dir_.path() / "Attributes"));
    dir_.write("sub/tri", read_text(dir_.path() / "tri"));
    const fs::path scene_file =
        dir_.write("sub/s.scn", scn("$ 1\n$ 1\n$ 1 1 0 tri 1 0 0 0 0 0 0\n"));
    const Scene scene = load_scene(scene_file, {}, diagnostics_);
    EXPECT_EQ(scene.source_files.at(2), (dir_.path() / "sub/tri").string());
}

TEST_F(SmallScene, TracesNameEveryFileAndLine) {
    RecordingDiagnostics r(true);
    load_scene(dir_.write("s.scn", scn("$ 1\n$ 1\n$ 1 1 0 tri 1 0 0 0 0 0 0\n")), {},
               r.diagnostics);
    const std::string tri = (dir_.path() / "tri").string();
    EXPECT_NE(std::find(r.traces.begin(), r.traces.end(), tri + ":1: vertex 1 = (1, 0, 0)"),
              r.traces.end());
    EXPECT_NE(std::find(r.traces.begin(), r.traces.end(),
                        (dir_.path() / "Attributes").string() +
                            ":4: attribute 3: colour (1, 1, 1) pow 2 tpow 2 e 1 a 0 d 0 s 0 t 0 "
                            "refraction (1, 1, 1) reflection cone 0 0 refraction cone 0 0"),
              r.traces.end());
}

TEST_F(SmallScene, Errors) {
    EXPECT_EQ(
        error(scn("$ 1\n$ 1\n$ 1 1 0 cube 1 0 0 0 0 0 0\n")),
        "s.scn:12: cannot open optical surface file 'cube' (cube): No such file or directory");
    EXPECT_EQ(error(scn("$ 0\n", "$ Attribs")),
              "s.scn:9: cannot open the attributes file 'Attribs' (Attribs): No such file or "
              "directory");
    ReaderDialect m;
    m.marks = true;
    EXPECT_EQ(
        error(scn("$@nothere\n$ 0\n"), m),
        "s.scn:10: cannot open the shape file 'nothere' (nothere): No such file or directory");
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 1 0 /dev/zero 1 0 0 0 0 0 0\n")),
              "s.scn:12: cannot open optical surface file '/dev/zero' (/dev/zero): a device, not "
              "a file");
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 9 0 tri 1 0 0 0 0 0 0\n")),
              "s.scn:12: optical surface 'tri' uses attribute 9, which is not defined");
    dir_.write("offset", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1\n0 3 0 1 2 0 0 1 5");
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 1 0 offset 1 0 0 0 0 0 0\n")),
              "offset:2: polygon 0 uses attribute 6 (attribute 1 of the optical surface + offset "
              "5), which is not defined");
    dir_.write("huge",
               "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1\n0 3 0 1 2 0 0 1 "
               "9223372036854775807");
    EXPECT_EQ(error(scn("$ 1\n$ 1\n$ 1 1 0 huge 1 0 0 0 0 0 0\n")),
              "huge:2: polygon 0 uses attribute 1 + offset 9223372036854775807, which is not "
              "defined");
    dir_.write("shapes", "$ 1\n$ 0 0 0 1 0 0 0\n");
    dir_.write("sphere", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1\n0 3 0 1 2 0 0 1 0 2 1");
    EXPECT_EQ(error(scn("$@shapes\n$ 1\n$ 1\n$ 1 1 0 sphere 1 0 0 0 0 0 0\n"), m),
              "sphere:2: polygon 0 (mark 2, a sphere) refers to shape 1, but the shape file "
              "defines 1 shape (numbered from 0)");
    dir_.write("cone", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1\n0 3 0 1 2 0 0 1 0 4 0");
    EXPECT_EQ(
        error(scn("$@shapes\n$ 1\n$ 1\n$ 1 1 0 cone 1 0 0 0 0 0 0\n"), m),
        "shapes:2: shape 0 is used as a cone by cone:2, but its two axis points are the same");
}

}  // namespace
}  // namespace rt::test
