// Texture-mapped optical surfaces (-V, manual 2.2): the grid file and the texture map read into
// one polygon per cell with its TextureCell, and every malformed file stopping at its line with
// "expected ..., found ..." (docs/formats.md, "Texture-mapped surfaces").
#include <cmath>

#include "rt/image/png_format.h"
#include "rt/scene/read/load_scene.h"
#include "rt/scene/textured_point.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

// A 2 x 3 grid of unit cells in the plane z = 0: row r at y = r, column c at x = c, so u runs
// along +x, v along +y and the outward side is +z. The lines of the points are 3 to 14.
const std::string kGrid =
    "# two rows of three cells\n"
    "2 3   # rows columns\n"
    "0 0 0\n1 0 0\n2 0 0\n3 0 0\n"
    "0 1 0\n1 1 0\n2 1 0\n3 1 0\n"
    "0 2 0\n1 2 0\n2 2 0\n3 2 0\n";

// One optical centre in the middle of the grid; the cells numbered in their green factors.
const std::string kMap =
    "2 3\n"
    "centre 1.5 1\n"
    "0 0.5 0 0 1 0.0 1\n0 0.5 0 0 1 0.1 1\n0 0.5 0 0 1 0.2 1\n"
    "0 0 0.25 90 1 0.3 1\n0 0 0.25 90 1 0.4 1\n0 0 0.25 90 1 0.5 1\n";

class TexturedScene : public ::testing::Test {
protected:
    void SetUp() override {
        dir_.write("Attributes",
                   "$ 2\n$ 1 1 1 2 2 0 0.1 0.9 0 0 1 0 0 0 0 1\n"
                   "$ 0.5 0.5 0.5 2 2 0 0.1 0.9 0 0 1 0 0 0 0 2\n");
        dir_.write("grid", kGrid);
        dir_.write("map", kMap);
    }
    // The .scn with no entities and the given texture-mapped surface lines.
    static std::string scn(const std::string& textured) {
        return "header\n$ 0 2 0 0 0 .5 2 1\n$ 0 0 -10 0 0 0\n$ 1\n$ 40 40\n$ 1\n$ 64 64\n"
               "$ 0 0 63 63\n$ Attributes\nentities\n$ 0\ntextured\n" +
               textured;
    }
    static std::string line(const std::string& placement = "2 1 2 3 0 0 90",
                            const std::string& size = "2 3") {
        return "$ 1\n$ 2 grid map " + placement + " " + size + "\n";
    }
    Scene load(const std::string& scene_text) {
        ReaderDialect v;
        v.textures = true;
        return load_scene(dir_.write("s.scn", scene_text), v, diagnostics_);
    }
    std::string error(const std::string& scene_text) {
        return without(input_error([&] { load(scene_text); }), dir_.path().string() + "/");
    }
    // The error of the default scene with one file replaced.
    std::string error_with(const std::string& file, const std::string& text) {
        dir_.write(file, text);
        return error(scn(line()));
    }

    TempDir dir_;
    Diagnostics diagnostics_;
};

void expect_near(const Vec3& got, const Vec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

TEST_F(TexturedScene, EveryCellIsOnePolygonWithItsTextureCell) {
    // Scale 2, turned 90 degrees about z (+x to +y), moved to (1, 2, 3).
    const Scene scene = load(scn(line()));
    EXPECT_TRUE(diagnostics_.warnings().empty());
    ASSERT_EQ(scene.polygons.size(), 6u);
    EXPECT_EQ(scene.positions.size(), 12u);  // shared by neighbouring cells
    ASSERT_EQ(scene.texture_cells.size(), 6u);
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].file, "grid");
    EXPECT_EQ(scene.surfaces[0].texture_map, "map");
    EXPECT_EQ(scene.surfaces[0].entity, 0);
    for (std::uint32_t id = 0; id < 6; ++id) {
        const Polygon& p = scene.polygons[id];
        ASSERT_EQ(p.texture_cell, static_cast<std::int32_t>(id));
        EXPECT_EQ(p.corner_count, 4u);
        EXPECT_FALSE(p.smooth);
        EXPECT_EQ(scene.attribute_of(p).index, 2);
        const TextureCell& cell = scene.texture_cells[id];
        EXPECT_EQ(cell.row, id / 3);
        EXPECT_EQ(cell.column, id % 3);
        EXPECT_DOUBLE_EQ(cell.color.g, 0.1 * id);
        EXPECT_EQ(surface_color(scene, id, scene.corner_position(p, 0)),
                  (Rgb{0.5, 0.5 * cell.color.g, 0.5}));
        // u (+x) turned to +y, v (+y) to -x; the outward side u x v stays +z.
        expect_near(p.normal, {0, 0, 1});
        expect_near(cell.tangent_u, {0, 1, 0});
        expect_near(cell.tangent_v, {-1, 0, 0});
        // (1.5, 1, 0) * 2 turned and moved.
        expect_near(cell.optical_centre, {1 - 2, 2 + 3, 3});
        // Curvatures per world unit: the grid is twice as large.
        EXPECT_EQ(cell.sphere, id < 3 ? 0.25 : 0.0);
        EXPECT_EQ(cell.cylinder, id < 3 ? 0.0 : 0.125);
        // Axis 0 runs along u, so across it is v; axis 90 along v, so across it is -u.
        expect_near(cell.across_axis, id < 3 ? Vec3{-1, 0, 0} : Vec3{0, -1, 0});
    }
    // Cell (1, 2) starts at point (1, 2), written on line 9; its corners run (1,2) (1,3) (2,3)
    // (2,2).
    EXPECT_EQ(scene.origin_of(5).to_string(), (dir_.path() / "grid").string() + ":9");
    const Polygon& last = scene.polygons[5];
    expect_near(scene.corner_position(last, 0), Vec3{1 - 2, 2 + 4, 3});
    expect_near(scene.corner_position(last, 1), Vec3{1 - 2, 2 + 6, 3});
    expect_near(scene.corner_position(last, 2), Vec3{1 - 4, 2 + 6, 3});
}

TEST_F(TexturedScene, TexturedSurfacesComeAfterTheEntitiesAndCountInAutoCentering) {
    dir_.write("tri", "3 0 0 0 0 1 1 0 0 2 0 1 0 3 0 0 1 1 1 2 2 2 0 1 0 3 0 1 2 0 0 1 0");
    std::string text = scn(line("1 0 0 0 0 0 0"));
    text.replace(text.find("$ 0 2 0"), 7, "$ 1 2 0");
    text.replace(text.find("entities\n$ 0"), 12, "entities\n$ 1\n$ 1\n$ 1 1 0 tri 1 0 0 -5 0 0 0");
    const Scene scene = load(text);
    ASSERT_EQ(scene.polygons.size(), 7u);
    EXPECT_EQ(scene.polygons[0].texture_cell, Polygon::kNoTexture);
    EXPECT_EQ(scene.polygons[1].texture_cell, 0);
    EXPECT_EQ(surface_color(scene, 0, scene.positions[0]), (Rgb{1, 1, 1}));
    // The box around the triangle (z = -5) and the grid (z = 0, up to (3, 2)).
    EXPECT_EQ(scene.view.look, (Vec3{1.5, 1, -2.5}));
}

TEST_F(TexturedScene, AMirroredGridKeepsItsFrameOnItsEdges) {
    // A negative scale turns the grid inside out: the normal flips, the tangents follow the
    // edges.
    const Scene scene = load(scn(line("-1 0 0 0 0 0 0")));
    const TextureCell& cell = scene.texture_cells[0];
    expect_near(scene.polygons[0].normal, {0, 0, -1});
    expect_near(cell.tangent_u, {-1, 0, 0});
    expect_near(cell.tangent_v, {0, -1, 0});
    expect_near(cell.optical_centre, {-1.5, -1, 0});
    EXPECT_EQ(cell.sphere, 0.5);
}

TEST_F(TexturedScene, ADegenerateCellIsSkippedWithAWarning) {
    // Points (1, 0) and (1, 1) moved onto (0, 0) and (0, 1): cell (0, 0) has two distinct
    // corners left.
    std::string grid = kGrid;
    grid.replace(grid.find("0 1 0\n1 1 0"), 11, "0 0 0\n1 0 0");
    dir_.write("grid", grid);
    const Scene scene = load(scn(line("1 0 0 0 0 0 0")));
    EXPECT_EQ(scene.polygons.size(), 5u);
    EXPECT_EQ(scene.polygons[0].texture_cell, 1);
    ASSERT_EQ(diagnostics_.warnings().size(), 1u);
    EXPECT_EQ(without(diagnostics_.warnings()[0], dir_.path().string() + "/"),
              "grid:3: cell (row 0, column 0) is degenerate (fewer than 3 distinct corners); "
              "skipped");
}

// A point far out of range can round its cell's area away: it is refused, not skipped with the
// cell as degenerate.
TEST_F(TexturedScene, AFarPointIsAnErrorEvenWhenItsCellLooksDegenerate) {
    std::string grid = kGrid;
    grid.replace(grid.find("0 0 0\n"), 6, "0 0 1e16\n");
    EXPECT_EQ(error_with("grid", grid),
              "grid:3: expected a grid point within the coordinate range -1e+15 to 1e+15, found "
              "(0, 0, 1e+16)");
}

TEST_F(TexturedScene, ACellOutOfItsPlaneIsAnError) {
    std::string grid = kGrid;
    // Point (1, 2) lifted: cell (0, 1), which starts at point (0, 1) on line 4, twists, its
    // corners a quarter of the lift off their mean plane.
    grid.replace(grid.find("2 1 0"), 5, "2 1 0.01");
    EXPECT_EQ(error_with("grid", grid),
              "grid:4: expected the corners of cell (row 0, column 1) in one plane, found them up "
              "to 0.0025 off it (more than 0.001 of the cell's size)");
    grid.replace(grid.find("2 1 0.01"), 8, "2 1 0.001");  // within the tolerance
    dir_.write("grid", grid);
    EXPECT_EQ(load(scn(line())).polygons.size(), 6u);
}

TEST_F(TexturedScene, TheGridFileIsCheckedLineByLine) {
    const auto with = [&](const std::string& from, const std::string& to) {
        std::string grid = kGrid;
        grid.replace(grid.find(from), from.size(), to);
        return error_with("grid", grid);
    };
    EXPECT_EQ(with("2 3   # rows columns", "3 2"),
              "grid:2: expected '2 3', the rows and columns of cells that s.scn:14 gives, found "
              "'3 2'");
    EXPECT_EQ(with("2 3   # rows columns", "2 3 1"),
              "grid:2: expected '2 3', the rows and columns of cells that s.scn:14 gives, found "
              "'2 3 1'");
    EXPECT_EQ(with("1 1 0\n", "1 1\n"),
              "grid:8: expected the z of point (row 1, column 1), found end of line");
    EXPECT_EQ(with("1 1 0\n", "1 1 0 1\n"),
              "grid:8: expected the end of the line after point (row 1, column 1), found '1'");
    EXPECT_EQ(with("1 1 0\n", "1 one 0\n"),
              "grid:8: expected the y of point (row 1, column 1), found 'one'");
    EXPECT_EQ(with("3 2 0\n", ""),
              "grid:13: expected point (row 2, column 3) of the 3 x 4 grid points, found end of "
              "file");
    EXPECT_EQ(error_with("grid", "# nothing\n"),
              "grid:1: expected the grid's rows and columns of cells, found end of file");
}

TEST_F(TexturedScene, LinesAfterTheGridAndTheMapAreIgnoredWithWarnings) {
    dir_.write("grid", kGrid + "4 4 4\n");
    dir_.write("map", kMap + "\n# more\n0 0 0 0 1 1 1\n0 0 0 0 1 1 1\n");
    const Scene scene = load(scn(line()));
    EXPECT_EQ(scene.polygons.size(), 6u);
    ASSERT_EQ(diagnostics_.warnings().size(), 2u);
    EXPECT_EQ(without(diagnostics_.warnings()[0], dir_.path().string() + "/"),
              "grid:15: 1 line after the grid's points ignored");
    EXPECT_EQ(without(diagnostics_.warnings()[1], dir_.path().string() + "/"),
              "map:11: 2 lines after the texture map's elements ignored");
}

TEST_F(TexturedScene, TheTextureMapIsCheckedLineByLine) {
    const auto with = [&](const std::string& from, const std::string& to) {
        std::string map = kMap;
        map.replace(map.find(from), from.size(), to);
        return error_with("map", map);
    };
    EXPECT_EQ(with("2 3\n", "2 2\n"),
              "map:1: expected '2 3', the rows and columns of cells that s.scn:14 gives, found "
              "'2 2'");
    EXPECT_EQ(with("centre 1.5 1\n", ""),
              "map:2: expected an optical centre line 'centre u v' before the elements, found '0'");
    EXPECT_EQ(with("centre 1.5 1\n", "center 1.5 1\n"),
              "map:2: expected 'centre', 'colour_map', 'normal_map' or the first element of the "
              "cells, found 'center'");
    EXPECT_EQ(with("centre 1.5 1\n", "centre 1.5\n"),
              "map:2: expected the v of optical centre 0, found end of line");
    EXPECT_EQ(with("centre 1.5 1\n", "centre 1.5 1 0\n"),
              "map:2: expected the end of the line after optical centre 0, found '0'");
    EXPECT_EQ(with("0 0.5 0 0 1 0.1 1\n", "1 0.5 0 0 1 0.1 1\n"),
              "map:4: expected the optical centre of the element of cell (row 0, column 1) (0 to "
              "0), found '1'");
    EXPECT_EQ(with("0 0.5 0 0 1 0.1 1\n", "0 0.5 0 0 1 1.1 1\n"),
              "map:4: expected the green factor of the element of cell (row 0, column 1) (0 to "
              "1), found '1.1'");
    EXPECT_EQ(with("0 0.5 0 0 1 0.1 1\n", "0 0.5 0 0 1 0.1\n"),
              "map:4: expected the blue factor of the element of cell (row 0, column 1), found "
              "end of line");
    EXPECT_EQ(with("0 0.5 0 0 1 0.1 1\n", "0 0.5 0 0 1 0.1 1 x\n"),
              "map:4: expected the end of the line after the element of cell (row 0, column 1), "
              "found 'x'");
    EXPECT_EQ(with("0 0.5 0 0 1 0.1 1\n", "0 0.5 0 nan 1 0.1 1\n"),
              "map:4: expected the cylinder axis of the element of cell (row 0, column 1), found "
              "'nan'");
    EXPECT_EQ(with("0 0 0.25 90 1 0.5 1\n", ""),
              "map:7: expected the element of cell (row 1, column 2) of the 2 x 3 cells, found "
              "end of file");
    EXPECT_EQ(error_with("map", "2 3\ncentre 0 0\n"),
              "map:2: expected the elements of the cells, found end of file");
    EXPECT_EQ(error_with("map", "2 3\n"),
              "map:1: expected an optical centre line 'centre u v', found end of file");
}

TEST_F(TexturedScene, TheMapNamesAColourMapAndANormalMap) {
    write_png(Image8{3, 2, std::vector<std::uint8_t>(18, 200)}, dir_.path() / "tint.png");
    write_png(Image8{1, 1, {128, 128, 255}}, dir_.path() / "bumps.png");
    std::string map = kMap;
    map.insert(map.find("0 0.5"), "colour_map tint.png\nnormal_map bumps.png  # flat\n");
    dir_.write("map", map);
    const Scene scene = load(scn(line()));
    ASSERT_EQ(scene.texture_grids.size(), 1u);
    const TextureGrid& grid = scene.texture_grids[0];
    EXPECT_EQ(grid.rows, 2u);
    EXPECT_EQ(grid.columns, 3u);
    ASSERT_EQ(scene.texture_images.size(), 2u);
    EXPECT_EQ(scene.texture_images[static_cast<std::size_t>(grid.colour_map)].width, 3);
    EXPECT_EQ(scene.texture_images[static_cast<std::size_t>(grid.normal_map)].rgb,
              (std::vector<std::uint8_t>{128, 128, 255}));
    // The colour map's 200 / 255 on top of cell 4's element (green 0.4) and the attribute's 0.5.
    const Rgb c = surface_color(scene, 4, scene.corner_position(scene.polygons[4], 0));
    EXPECT_NEAR(c.g, 0.5 * 0.4 * 200 / 255, 1e-12);
}

TEST_F(TexturedScene, PictureLinesAreCheckedToo) {
    write_png(Image8{1, 1, {1, 2, 3}}, dir_.path() / "tint.png");
    const auto with = [&](const std::string& lines) {
        std::string map = kMap;
        map.insert(map.find("0 0.5"), lines);
        return error_with("map", map);
    };
    EXPECT_EQ(with("colour_map tint.png\ncolour_map tint.png\n"),
              "map:4: a second colour_map line (the first is at line 3)");
    EXPECT_EQ(with("normal_map\n"),
              "map:3: expected the file name of the normal_map, found end "
              "of line");
    EXPECT_EQ(with("normal_map a b\n"),
              "map:3: expected the end of the line after the file name of the normal_map, found "
              "'b'");
    EXPECT_EQ(with("colour_map none.png\n").substr(0, 40),
              "map:3: colour map 'none.png': cannot ope");
    dir_.write("text.png", "not a picture");
    EXPECT_EQ(with("normal_map text.png\n").substr(0, 56),
              "map:3: normal map 'text.png': expected a PNG picture, fo");
}

TEST_F(TexturedScene, EachPictureIsCheckedBeforeItIsDecodedAndAFileIsDecodedOnce) {
    write_png(Image8{3, 2, std::vector<std::uint8_t>(18, 200)}, dir_.path() / "tint.png");
    std::string map = kMap;
    map.insert(map.find("0 0.5"), "colour_map tint.png\nnormal_map ./tint.png\n");
    dir_.write("map", map);
    std::vector<std::vector<TexturePicture>> seen;
    ReaderDialect v;
    v.textures = true;
    const Scene scene =
        load_scene(dir_.write("s.scn", scn(line())), v, diagnostics_,
                   [&](const std::vector<TexturePicture>& pictures) { seen.push_back(pictures); });
    // One file under two names: decoded once, checked once, shared by both maps.
    ASSERT_EQ(seen.size(), 1u);
    ASSERT_EQ(seen[0].size(), 1u);
    EXPECT_EQ(seen[0][0].name, "tint.png");
    EXPECT_EQ(seen[0][0].where.to_string(), (dir_.path() / "map").string() + ":3");
    EXPECT_EQ(seen[0][0].bytes, 18u);
    ASSERT_EQ(scene.texture_images.size(), 1u);
    EXPECT_EQ(scene.texture_images[0].name, "tint.png");
    EXPECT_EQ(scene.texture_grids[0].colour_map, scene.texture_grids[0].normal_map);

    // A refusal stops the load before the picture is decoded: no pixel of it is read.
    const auto refuse = [](const std::vector<TexturePicture>& pictures) {
        throw UsageError("refused " + pictures.back().name);
    };
    try {
        load_scene(dir_.path() / "s.scn", v, diagnostics_, refuse);
        FAIL() << "the check was not called";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "refused tint.png");
    }
}

TEST_F(TexturedScene, APictureClaimingMoreThanItsDataCanHoldIsRefusedUnread) {
    // A 1 x 1 PNG whose header says 16384 x 16384: its IHDR's width at 16, height at 20, the
    // chunk's CRC at 29 over bytes 12 to 28 (libpng checks it).
    std::vector<std::uint8_t> bytes = encode_png(Image8{1, 1, {1, 2, 3}});
    for (const std::size_t at : {std::size_t{16}, std::size_t{20}}) {
        bytes[at + 1] = 0;
        bytes[at + 2] = 0x40;
        bytes[at + 3] = 0;
    }
    std::uint32_t crc = 0xffffffffU;
    for (std::size_t i = 12; i < 29; ++i) {
        crc ^= bytes[i];
        for (int bit = 0; bit < 8; ++bit) {
            crc = (crc >> 1) ^ (0xedb88320U & (0U - (crc & 1U)));
        }
    }
    crc ^= 0xffffffffU;
    for (int i = 0; i < 4; ++i) {
        bytes[29 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
    }
    dir_.write("huge.png", std::string(bytes.begin(), bytes.end()));
    std::string map = kMap;
    map.insert(map.find("0 0.5"), "colour_map huge.png\n");
    dir_.write("map", map);
    bool checked = false;
    ReaderDialect v;
    v.textures = true;
    const std::string message =
        without(input_error([&] {
                    load_scene(dir_.write("s.scn", scn(line())), v, diagnostics_,
                               [&](const auto&) { checked = true; });
                }),
                dir_.path().string() + "/");
    EXPECT_FALSE(checked);
    EXPECT_EQ(message.substr(0, message.find('(')),
              "map:3: colour map 'huge.png': expected a PNG picture whose compressed data ");
    EXPECT_NE(message.find("bytes) can hold its 16384 x 16384 pixels, found 805306368 bytes of "
                           "pixel rows to unpack from them (deflate unpacks at most 1032 bytes "
                           "from each)"),
              std::string::npos)
        << message;
}

TEST_F(TexturedScene, MissingFilesAndAttributesAreNamedAtTheScnLine) {
    EXPECT_EQ(error(scn("$ 1\n$ 2 nogrid map 1 0 0 0 0 0 0 2 3\n")),
              "s.scn:14: cannot open polygon file 'nogrid' (nogrid): No such file or directory");
    EXPECT_EQ(error(scn("$ 1\n$ 2 grid nomap 1 0 0 0 0 0 0 2 3\n")),
              "s.scn:14: cannot open texture map 'nomap' (nomap): No such file or directory");
    EXPECT_EQ(error(scn("$ 1\n$ 7 grid map 1 0 0 0 0 0 0 2 3\n")),
              "s.scn:14: optical surface 'grid' uses attribute 7, which is not defined");
}

TEST_F(TexturedScene, DashDfTracesTheLinesThePointsAndTheElements) {
    RecordingDiagnostics recording(true);
    ReaderDialect v;
    v.textures = true;
    load_scene(dir_.write("s.scn", scn(line())), v, recording.diagnostics);
    const auto traced = [&](const std::string& text) {
        for (const std::string& t : recording.traces) {
            if (without(t, dir_.path().string() + "/") == text) {
                return true;
            }
        }
        return false;
    };
    EXPECT_TRUE(
        traced("s.scn:14: texture-mapped surface 'grid' texture map 'map' attribute 2 "
               "scale 2 translation (1, 2, 3) rotation (0, 0, 90) grid 2 x 3"));
    EXPECT_TRUE(traced("grid:14: point (row 2, column 3) = (3, 2, 0)"));
    EXPECT_TRUE(traced("map:2: optical centre 0 at u 1.5 v 1"));
    EXPECT_TRUE(
        traced("map:8: the element of cell (row 1, column 2): centre 0 sphere 0 cylinder "
               "0.25 axis 90 colour (1, 0.5, 1)"));
}

}  // namespace
}  // namespace rt::test
