#include "rt/scene/read/scn_reader.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

// The manual's .scn (2.2) up to the entity count; {S} marks the sample resolution line, {W} the
// output matrix, {E} the entities.
std::string scene_text(const std::string& sample = "$ 1",
                       const std::string& window = "$ 0 0 511 399",
                       const std::string& entities =
                           "$ 1\n$ 1 optical surface\n"
                           "$ 1 12 0 cube 3 2 0 2 0 20 0\n") {
    return "center lghtick sptncde octr graphmode normallength maxdepth maxdist\n"
           "$ 0 2 1 4 3 .5 2 1\n"
           "eyept & lookpt\n"
           "$ 10.0 30.0 -75.0 0.0 0.0 0.0\n"
           "screendist\n"
           "$ 25.0\n"
           "view angles x,y\n"
           "$ 32.0 25.0\n"
           "sample resolution x,y\n" +
           sample +
           "\n"
           "viewarea in pixels x,y (integers)\n"
           "$ 512 400\n"
           "output matrix boundaries (integers)\n" +
           window +
           "\n"
           "name of file with list of attributes\n"
           "$ Attributes\n"
           "entities\n" +
           entities;
}

ScnFile read(const std::string& bytes, const ReaderDialect& dialect, Diagnostics& d) {
    const SourceText text = text_file("s.scn", bytes);
    return read_scn(text, dialect, d);
}

std::string error(const std::string& bytes, const ReaderDialect& dialect = {}) {
    Diagnostics d;
    return input_error([&] { read(bytes, dialect, d); });
}

TEST(ScnReader, ReadsTheManualsLayout) {
    Diagnostics d;
    const ScnFile scn = read(scene_text(), {}, d);
    EXPECT_EQ(scn.view.sample_resolution_x, 1);
    EXPECT_EQ(scn.view.sample_resolution_y, 1);
    ASSERT_TRUE(scn.attributes_file);
    EXPECT_EQ(scn.attributes_file->name, "Attributes");
    EXPECT_EQ(scn.attributes_file->where.to_string(), "s.scn:16");
    EXPECT_FALSE(scn.shape_file);
    ASSERT_EQ(scn.surfaces.size(), 1u);
    const ScnSurface& s = scn.surfaces[0];
    EXPECT_EQ(s.surface.file, "cube");
    EXPECT_EQ(s.surface.entity, 1);
    EXPECT_EQ(s.surface.filetype, 0);
    EXPECT_EQ(s.surface.attribute_number, 12);
    EXPECT_FALSE(s.surface.smooth_shaded);
    EXPECT_EQ(s.surface.where.to_string(), "s.scn:20");
    EXPECT_EQ(s.placement.scale, 3.0);
    EXPECT_EQ(s.placement.translation, (Vec3{2, 0, 2}));
    EXPECT_EQ(s.placement.rotation_degrees, (Vec3{0, 20, 0}));
    EXPECT_TRUE(d.warnings().empty());
}

TEST(ScnReader, SampleResolutionTakesTwoNumbersOnlyFromItsOwnLine) {
    Diagnostics d;
    EXPECT_EQ(read(scene_text("$ 2 3"), {}, d).view.sample_resolution_y, 3);
    EXPECT_EQ(read(scene_text("$ 2 3"), {}, d).view.sample_resolution_x, 2);
    const ScnFile one = read(scene_text("$ 4 samples a side"), {}, d);
    EXPECT_EQ(one.view.sample_resolution_x, 4);
    EXPECT_EQ(one.view.sample_resolution_y, 4);
    EXPECT_EQ(one.view.width, 512);
    EXPECT_EQ(error(scene_text("$ 0")),
              "s.scn:10: expected the sample resolution (1 to 64), found '0'");
    EXPECT_EQ(error(scene_text("$ 2 65")),
              "s.scn:10: expected the sample resolution y (1 to 64), found '65'");
}

TEST(ScnReader, ItemsMayShareOrSplitLines) {
    Diagnostics d;
    const std::string packed =
        "$0 2 1 4\n$3 .5 2 1\n$ 10 30 -75\n$ 0 0 0 25\n$ 32 25\n$ 2 2\n$ 512 400 0 0 511 399 "
        "window\n$ Attributes\n$ 1 1 1 12 0 cube 3 2 0 2 0 20 0 $ a comment\n";
    const ScnFile scn = read(packed, {}, d);
    EXPECT_EQ(scn.header.maxdist, 1.0);
    EXPECT_EQ(scn.view.eye, (Vec3{10, 30, -75}));
    EXPECT_EQ(scn.view.screen_distance, 25.0);
    EXPECT_EQ(scn.view.sample_resolution_y, 2);
    EXPECT_EQ(scn.view.window, (PixelRect{0, 0, 511, 399}));
    EXPECT_EQ(scn.attributes_file->name, "Attributes");
    // "window" after the output matrix is a comment, so a file name must begin its own line.
    // The entity count, the surface count and the surface on one line, then a comment.
    ASSERT_EQ(scn.surfaces.size(), 1u);
    EXPECT_EQ(scn.surfaces[0].placement.rotation_degrees, (Vec3{0, 20, 0}));
}

TEST(ScnReader, CrlfIndentationAndNoFinalNewline) {
    Diagnostics d;
    std::string text = scene_text();
    std::string crlf;
    for (const char c : text) {
        crlf += c == '\n' ? std::string("\r\n\t  ") : std::string(1, c);
    }
    crlf.resize(crlf.size() - 5);  // no final line break
    const ScnFile scn = read(crlf, {}, d);
    ASSERT_EQ(scn.surfaces.size(), 1u);
    EXPECT_EQ(scn.surfaces[0].placement.rotation_degrees, (Vec3{0, 20, 0}));
}

TEST(ScnReader, OutputMatrixOnePastTheEdgeIsClampedWithAWarning) {
    Diagnostics d;
    const ScnFile scn = read(scene_text("$ 1", "$ 0 0 512 400"), {}, d);
    EXPECT_EQ(scn.view.window, (PixelRect{0, 0, 511, 399}));
    EXPECT_EQ(d.warnings(),
              (std::vector<std::string>{
                  "s.scn:14: the output matrix's right edge 512 is one past the last column; "
                  "using 511",
                  "s.scn:14: the output matrix's bottom edge 400 is one past the last row; using "
                  "399"}));
}

TEST(ScnReader, OutputMatrixErrors) {
    EXPECT_EQ(error(scene_text("$ 1", "$ 0 0 513 399")),
              "s.scn:14: the output matrix 0 0 513 399 is outside the 512 x 400 view area "
              "(columns 0 to 511, rows 0 to 399)");
    EXPECT_EQ(error(scene_text("$ 1", "$ -1 0 10 10")),
              "s.scn:14: the output matrix -1 0 10 10 is outside the 512 x 400 view area "
              "(columns 0 to 511, rows 0 to 399)");
    EXPECT_EQ(error(scene_text("$ 1", "$ 10 0 5 399")),
              "s.scn:14: the output matrix 10 0 5 399 is reversed: it reads left top right bottom");
    EXPECT_EQ(error(scene_text("$ 1", "$ 0 0 511")),
              "s.scn:16: expected the output matrix's bottom (-1000000000 to 1000000000), found "
              "'Attributes'");
}

TEST(ScnReader, WithSmoothShadeField) {
    Diagnostics d;
    ReaderDialect po;
    po.smooth_shade_field = true;
    const std::string entities =
        "$ 1\n$ 2 surfaces\n$ 1 12 0 1 cube 3 2 0 2 0 20 0\n"
        "$ 2 0 2 0 prinz 1 0 0 0 0 0 0\n";
    const ScnFile scn = read(scene_text("$ 1", "$ 0 0 511 399", entities), po, d);
    ASSERT_EQ(scn.surfaces.size(), 2u);
    EXPECT_TRUE(scn.surfaces[0].surface.smooth_shaded);
    EXPECT_FALSE(scn.surfaces[1].surface.smooth_shaded);
    EXPECT_EQ(scn.surfaces[1].surface.filetype, 2);
    EXPECT_EQ(
        error(scene_text("$ 1", "$ 0 0 511 399", "$ 1\n$ 1\n$ 1 12 0 2 cube 3 0 0 0 0 0 0\n"), po),
        "s.scn:20: expected the smooth-shade field of -Po/-Pt (0 to 1), "
        "found '2'");
    EXPECT_EQ(
        error(scene_text("$ 1", "$ 0 0 511 399", "$ 1\n$ 1\n$ 1 12 0 cube 3 0 0 0 0 0 0\n"), po),
        "s.scn:20: expected the smooth-shade field of -Po/-Pt (0 to 1), found 'cube'");
    EXPECT_EQ(
        error(scene_text("$ 1", "$ 0 0 511 399", "$ 1\n$ 1\n$ 1 12 1 1 p 3 0 0 0 0 0 0\n"), po),
        "s.scn:20: optical surface 'p' has filetype 1 (Phigs+), whose polygons cannot be "
        "smooth-shaded");
}

TEST(ScnReader, ASmoothShadeFieldWithoutPoIsExplained) {
    EXPECT_EQ(
        error(scene_text("$ 1", "$ 0 0 511 399", "$ 1\n$ 1\n$ 1 12 0 1 cube 3 0 0 0 0 0 0\n")),
        "s.scn:20: expected the scale of optical surface '1', found 'cube' (a fourth number "
        "before the file name is the smooth-shade field, read only with -Po or -Pt)");
}

TEST(ScnReader, InlineAttributesWithDf) {
    Diagnostics d;
    ReaderDialect df;
    df.attributes_inline = true;
    std::string text = scene_text();
    const std::string inline_block =
        "attributes\n$ 2\n$ 0.0 0.2 0.98 2.0 0.0 0.0 0.05 0.9 0.1 0.0 1.05 4.0 1.0 0.0 0.0 0\n"
        "$ 0.8 0.2 0.0 2.0 0.0 0.0 0.05 0.8 0.4 0.0 1.05 4.0 1.0 0.0 0.0 12\n";
    text.replace(text.find("$ Attributes\n"), 13, inline_block);
    const ScnFile scn = read(text, df, d);
    EXPECT_FALSE(scn.attributes_file);
    ASSERT_EQ(scn.inline_attributes.size(), 2u);
    EXPECT_EQ(scn.inline_attributes[1].index, 12);
    EXPECT_EQ(scn.surfaces.size(), 1u);
    // -Of is -Df with -Dp: the power fields are absent.
    ReaderDialect of = df;
    of.no_power_fields = true;
    std::string old = scene_text();
    old.replace(old.find("$ Attributes\n"), 13,
                "$ 1\n$ 0.0 0.2 0.98 0.0 0.05 0.9 0.1 0.0 1.05 4.0 1.0 0.0 0.0 12\n");
    const ScnFile of_scn = read(old, of, d);
    EXPECT_EQ(of_scn.inline_attributes.at(0).specular_exponent, 2.0);
    EXPECT_EQ(of_scn.inline_attributes.at(0).diffuse, 0.9);
}

TEST(ScnReader, ShapeFileLineInBothForms) {
    Diagnostics d;
    ReaderDialect m;
    m.marks = true;
    for (const std::string line : {"$@shapes\n", "$ @shapes\n", "$ @ shapes\n"}) {
        std::string text = scene_text();
        text.replace(text.find("entities\n"), 9, line + "entities\n");
        const ScnFile scn = read(text, m, d);
        ASSERT_TRUE(scn.shape_file) << line;
        EXPECT_EQ(scn.shape_file->name, "shapes");
        EXPECT_EQ(scn.shape_file->where.to_string(), "s.scn:17");
        EXPECT_EQ(scn.surfaces.size(), 1u);
    }
}

TEST(ScnReader, ShapeFileLineAndMMustGoTogether) {
    ReaderDialect m;
    m.marks = true;
    EXPECT_EQ(error(scene_text(), m),
              "s.scn:18: expected the shape file line $@name (-M needs one), found '1'");
    std::string text = scene_text();
    text.replace(text.find("entities\n"), 9, "$@shapes\nentities\n");
    EXPECT_EQ(error(text), "s.scn:17: the scene names a shape file; use -M");
}

// The manual's two lines after the entities (2.2).
const std::string kTextureLines = "$ 1\n$ 0 lenspts.dat prescrip.dat 0.25 -5 -8 0 0 0 0 8 34\n";

TEST(ScnReader, DashVReadsTheTextureMappedSurfaces) {
    ReaderDialect v;
    v.textures = true;
    Diagnostics d;
    const ScnFile scn = read(scene_text() + kTextureLines, v, d);
    ASSERT_EQ(scn.textured_surfaces.size(), 1u);
    const ScnTexturedSurface& t = scn.textured_surfaces[0];
    EXPECT_EQ(t.attribute_number, 0);
    EXPECT_EQ(t.polygon_file.name, "lenspts.dat");
    EXPECT_EQ(t.texture_map.name, "prescrip.dat");
    EXPECT_EQ(t.texture_map.where.to_string(), "s.scn:22");
    EXPECT_EQ(t.placement.scale, 0.25);
    EXPECT_EQ(t.placement.translation, (Vec3{-5, -8, 0}));
    EXPECT_EQ(t.placement.rotation_degrees, (Vec3{0, 0, 0}));
    EXPECT_EQ(t.rows, 8);
    EXPECT_EQ(t.columns, 34);
    EXPECT_EQ(t.where.to_string(), "s.scn:22");
    EXPECT_TRUE(d.warnings().empty());
}

TEST(ScnReader, TextureLinesNeverCarryASmoothShadeField) {
    ReaderDialect v;
    v.textures = true;
    v.smooth_shade_field = true;
    std::string text = scene_text();
    text.replace(text.find("cube"), 4, "0 cube");
    Diagnostics d;
    EXPECT_EQ(read(text + kTextureLines, v, d).textured_surfaces.at(0).columns, 34);
    EXPECT_EQ(error(text + "$ 1\n$ 0 0 lenspts.dat prescrip.dat 0.25 -5 -8 0 0 0 0 8 34\n", v),
              "s.scn:22: expected the scale of texture-mapped surface '0', found 'prescrip.dat' (a "
              "texture-mapped surface has no smooth-shade field, even with -Po or -Pt)");
}

TEST(ScnReader, DashVWithoutTheLinesNamesWhereTheyWereExpected) {
    ReaderDialect v;
    v.textures = true;
    EXPECT_EQ(error(scene_text(), v),
              "s.scn:20: expected the texture-mapped surface count (-V), found end of file");
    EXPECT_EQ(error(scene_text() + "$ 2\n$ 0 a b 1 0 0 0 0 0 0 1 1\n", v),
              "s.scn:22: expected the texture-mapped surface's attribute number, found end of "
              "file");
}

TEST(ScnReader, TextureLinesAreCheckedFieldByField) {
    ReaderDialect v;
    v.textures = true;
    const auto with = [&](const std::string& line) {
        return error(scene_text() + "$ 1\n$ " + line + "\n", v);
    };
    EXPECT_EQ(with("0 lenspts.dat prescrip.dat 0 -5 -8 0 0 0 0 8 34"),
              "s.scn:22: the scale of texture-mapped surface 'lenspts.dat' must not be 0");
    EXPECT_EQ(with("0 lenspts.dat prescrip.dat 0.25 -5 -8 0 0 0 0 0 34"),
              "s.scn:22: expected the rows of cells of texture-mapped surface 'lenspts.dat' (1 to "
              "50000000), found '0'");
    EXPECT_EQ(with("0 lenspts.dat prescrip.dat 0.25 -5 -8 0 0 0 0 8 2.5"),
              "s.scn:22: expected the columns of cells of texture-mapped surface 'lenspts.dat' (1 "
              "to 50000000), found '2.5'");
    EXPECT_EQ(with("0 lenspts.dat prescrip.dat 0.25 -5 -8 0 0 0 0 10000 10000"),
              "s.scn:22: the grid of texture-mapped surface 'lenspts.dat' has 10000 x 10000 "
              "cells, more than the limit of 50000000 points");
    EXPECT_EQ(with("0 lenspts.dat prescrip.dat 0.25 -5 -8 0 0 x 0 8 34"),
              "s.scn:22: expected the rotation about y, found 'x'");
    EXPECT_EQ(with("x lenspts.dat prescrip.dat 0.25 -5 -8 0 0 0 0 8 34"),
              "s.scn:22: expected the texture-mapped surface's attribute number (a whole number), "
              "found 'x'");
    EXPECT_EQ(error(scene_text() + "$ -1\n", v),
              "s.scn:21: expected the texture-mapped surface count (-V) (0 or more), found '-1'");
}

TEST(ScnReader, LinesAfterTheTextureMappedSurfacesAreIgnoredWithAWarning) {
    ReaderDialect v;
    v.textures = true;
    Diagnostics d;
    const ScnFile scn = read(scene_text() + "$ 0 none\n$ 1 2 3\n$ 4\n", v, d);
    EXPECT_TRUE(scn.textured_surfaces.empty());
    ASSERT_EQ(d.warnings().size(), 1u);
    EXPECT_EQ(d.warnings()[0], "s.scn:22: 2 lines after the texture-mapped surfaces ignored");
}

TEST(ScnReader, HeaderAndViewErrors) {
    const auto with = [](const std::string& from, const std::string& to) {
        std::string text = scene_text();
        text.replace(text.find(from), from.size(), to);
        return error(text);
    };
    EXPECT_EQ(with("$ 0 2 1 4 3 .5 2 1", "$ 2 2 1 4 3 .5 2 1"),
              "s.scn:2: expected the header's center (0 to 1), found '2'");
    EXPECT_EQ(with("$ 0 2 1 4 3 .5 2 1", "$ 0 3 1 4 3 .5 2 1"),
              "s.scn:2: expected the header's lghtick (0 to 2), found '3'");
    EXPECT_EQ(with("$ 0 2 1 4 3 .5 2 1", "$ 0 2 1 4 3 .5 65 1"),
              "s.scn:2: expected the header's maxdepth (0 to 64), found '65'");
    EXPECT_EQ(with("$ 0 2 1 4 3 .5 2 1", "$ 0 2 1 4 3 .5 2 -1"),
              "s.scn:2: expected the header's maxdist (0 or more), found '-1'");
    EXPECT_EQ(with("$ 0 2 1 4 3 .5 2 1", "$ 0 2 1 4 3 nan 2 1"),
              "s.scn:2: expected the header's normallength, found 'nan'");
    EXPECT_EQ(with("$ 0 2 1 4 3 .5 2 1", "$ 0 2 99999 4 3 .5 2 1"),
              "s.scn:2: expected the header's sptncde (0 to 322), found '99999'");
    // SEADS builds at most 322 voxels a side: the reader refuses more, at the header's line.
    EXPECT_EQ(with("$ 0 2 1 4 3 .5 2 1", "$ 0 2 323 0 3 .5 2 1"),
              "s.scn:2: expected the header's sptncde (0 to 322), found '323'");
    EXPECT_EQ(with("$ 10.0 30.0 -75.0 0.0 0.0 0.0", "$ 1 2 3 1 2 3"),
              "s.scn:4: the eye point and the look point are the same (1, 2, 3)");
    EXPECT_EQ(with("$ 10.0 30.0 -75.0 0.0 0.0 0.0", "$ 10.0 30.0 -75.0 0.0 0.0 x"),
              "s.scn:4: expected the look point's z (-1e+15 to 1e+15), found 'x'");
    // The least screen distance is a millionth of the eye's largest coordinate (75 here): a
    // screen the eye's rounding swallows gave eye rays of no direction, and a black picture.
    EXPECT_EQ(with("$ 25.0", "$ 0"),
              "s.scn:6: expected the screen distance (between 7.5e-05 and 1e+15), found '0'");
    EXPECT_EQ(with("$ 25.0", "$ 1e-100"),
              "s.scn:6: expected the screen distance (between 7.5e-05 and 1e+15), found '1e-100'");
    EXPECT_EQ(with("$ 32.0 25.0", "$ 180 25.0"),
              "s.scn:8: expected the view angle x in degrees (between 0 and 180), found '180'");
    EXPECT_EQ(with("$ 32.0 25.0", "$ 32.0 -inf"),
              "s.scn:8: expected the view angle y in degrees, found '-inf'");
    EXPECT_EQ(with("$ 512 400", "$ 0 400"),
              "s.scn:12: expected the view area's width in pixels (1 to 16384), found '0'");
    EXPECT_EQ(with("$ 512 400", "$ 512 100000"),
              "s.scn:12: expected the view area's height in pixels (1 to 16384), found '100000'");
    EXPECT_EQ(with("$ 512 400", "$ 512 400.5"),
              "s.scn:12: expected the view area's height in pixels (1 to 16384), found '400.5'");
    // Attributes written in the .scn start with their count where the file's name stands.
    EXPECT_EQ(with("$ Attributes", "$ 13"),
              "s.scn:16: expected the name of the attributes file, found '13', a number: "
              "attributes written in the .scn itself, after their count, are read with -Df");
}

TEST(ScnReader, EntityErrors) {
    const auto entities = [](const std::string& e) {
        return error(scene_text("$ 1", "$ 0 0 511 399", e));
    };
    EXPECT_EQ(entities(""), "s.scn:17: expected the entity count, found end of file");
    EXPECT_EQ(entities("$ -3\n"), "s.scn:18: expected the entity count (0 or more), found '-3'");
    EXPECT_EQ(entities("$ 2000000\n"),
              "s.scn:18: The entity count is 2000000, more than the limit of 1000000");
    EXPECT_EQ(entities("$ three\n"),
              "s.scn:18: expected the entity count (a whole number), found 'three'");
    EXPECT_EQ(entities("$ 2\n$ 1\n$ 1 12 0 cube 3 2 0 2 0 20 0\n"),
              "s.scn:20: expected the optical surface count of entity 2, found end of file");
    EXPECT_EQ(entities("$ 1\n$ 1\n$ 1 12 4 cube 3 2 0 2 0 20 0\n"),
              "s.scn:20: expected the filetype (0 to 3), found '4'");
    EXPECT_EQ(entities("$ 1\n$ 1\n$ 1 12 0 cube 0 2 0 2 0 20 0\n"),
              "s.scn:20: the scale of optical surface 'cube' must not be 0");
    EXPECT_EQ(entities("$ 1\n$ 1\n$ 1 12 0 cube 3 2 0 2 0 20\n"),
              "s.scn:20: expected the rotation about z, found end of file");
    EXPECT_EQ(entities("$ 1\n$ 1\n$ 1 x 0 cube 3 2 0 2 0 20 0\n"),
              "s.scn:20: expected the optical surface's attribute number (a whole number), found "
              "'x'");
}

// The items are a token stream: a missing number shifts every later item, and the error is where
// the stream first stops fitting (docs/formats.md says so).
TEST(ScnReader, AMissingNumberShiftsLaterItems) {
    std::string text = scene_text();
    text.replace(text.find("$ 10.0 30.0 -75.0 0.0 0.0 0.0"), 29, "$ 10.0 30.0 -75.0 0.0 0.0");
    EXPECT_EQ(error(text), "s.scn:12: expected the sample resolution (1 to 64), found '512'");
}

TEST(ScnReader, NoEntitiesIsAllowed) {
    Diagnostics d;
    EXPECT_TRUE(read(scene_text("$ 1", "$ 0 0 511 399", "$ 0\n"), {}, d).surfaces.empty());
}

TEST(ScnReader, TracesEachItemWithDf) {
    RecordingDiagnostics r(true);
    read(scene_text(), {}, r.diagnostics);
    ASSERT_GE(r.traces.size(), 9u);
    EXPECT_EQ(r.traces[0],
              "s.scn:2: header: center 0 lghtick 2 sptncde 1 octr 4 graphmode 3 normallength 0.5 "
              "maxdepth 2 maxdist 1");
    EXPECT_EQ(r.traces[1], "s.scn:4: eye (10, 30, -75) look (0, 0, 0)");
    EXPECT_EQ(r.traces.back(),
              "s.scn:20: entity 1: optical surface 'cube' filetype 0 attribute 12 smooth 0 scale "
              "3 translation (2, 0, 2) rotation (0, 20, 0)");
}

}  // namespace
}  // namespace rt::test
