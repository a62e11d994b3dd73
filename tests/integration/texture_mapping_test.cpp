// Texture-mapped optical surfaces (-V) in whole renders: a cylindrical prescription displaces a
// straight edge seen through it where Snell's law at a cylinder of that radius puts it (computed
// here from the geometry of the cylinder, not with rt's code), and a flat, white prescription
// draws exactly the picture of the same grid as a plain polygon file.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "rt/accel/accelerator_stack.h"
#include "rt/app/run_settings.h"
#include "rt/app/switch_parser.h"
#include "rt/core/diagnostics.h"
#include "rt/image/png_format.h"
#include "rt/render/film_window.h"
#include "rt/render/renderer.h"
#include "rt/scene/read/load_scene.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// The film's floats (r, g, b per pixel, row by row) of the scene rendered with these switches.
std::vector<float> render_file(const fs::path& scene_file,
                               const std::vector<std::string>& switches) {
    std::vector<std::string> args = {scene_file.string()};
    args.insert(args.end(), switches.begin(), switches.end());
    const Options options = parse_command_line(args);
    Diagnostics diagnostics;
    const Scene scene = load_scene(scene_file, options.dialect, diagnostics);
    EXPECT_TRUE(diagnostics.warnings().empty()) << diagnostics.warnings().front();
    RenderSettings settings;
    settings.shading = run_shading(options);
    settings.window = film_window(scene.view.window, options.start_line);
    const AcceleratorStack stack(scene, options.accel, AccelMessages{});
    RenderObserver silent;
    RenderStatistics statistics;
    return render(scene, stack.top(), settings, silent, statistics).data();
}

// A filetype-0 rectangle in the plane z = `z` from (x0, y0) to (x1, y1), outward toward -z.
std::string rectangle(double x0, double y0, double x1, double y1, double z) {
    return fmt::format(
        "4\n0 {0} {1} {4}\n1 {2} {1} {4}\n2 {2} {3} {4}\n3 {0} {3} {4}\n"
        "4\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n1\n0 4 0 1 2 3 0 0 -1 0\n",
        x0, y0, x1, y1, z);
}

// ---- An edge seen through a cylinder -------------------------------------------------------

constexpr int kWidth = 401;            // pixels in the one row drawn
constexpr double kHalfAngle = 10.0;    // degrees: half the view angle across
constexpr double kEyeDistance = 20.0;  // the eye at (0, 0, -20), the sheet in z = 0
constexpr double kBackdrop = 10.0;     // the lamp's plane, z = 10
constexpr double kEdge = 2.0;          // the lamp covers x < 2 there
constexpr double kIndex = 1.5;         // the sheet's glass
constexpr double kHalfSheet = 4.0;     // the sheet spans x in [-4, 4]

// Where the lamp's edge shows in the row, in pixels from the left (continuous), for a sheet whose
// surface is a cylinder of curvature k (axis along y, bulging toward the eye for k > 0), or flat
// (k = 0). Each ray is refracted once, where it meets the plane z = 0, with the normal the
// cylinder has above that point; x0 is where the edge's ray meets the sheet.
double predicted_edge(double k, double& x0) {
    const double tan_half = std::tan(kHalfAngle * std::numbers::pi / 180.0);
    const auto lamp_x = [&](double pixel, double& at_sheet) {
        const double sx = (2.0 * pixel / kWidth - 1.0) * tan_half;  // the screen, 1 from the eye
        const double norm = std::sqrt(sx * sx + 1.0);
        const double dx = sx / norm;
        const double dz = 1.0 / norm;
        at_sheet = kEyeDistance * sx;
        // The cylinder of radius 1/|k| whose axis runs along y at z = 1/k: the outward normal at
        // lateral offset x is (k x, 0, -sqrt(1 - (k x)^2)).
        const double nx = k * at_sheet;
        const double nz = -std::sqrt(1.0 - nx * nx);
        // Snell's law, n1 sin(i) = n2 sin(t), in vector form.
        const double eta = 1.0 / kIndex;
        const double cos_i = -(dx * nx + dz * nz);
        const double cos_t = std::sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i));
        const double rx = eta * dx + (eta * cos_i - cos_t) * nx;
        const double rz = eta * dz + (eta * cos_i - cos_t) * nz;
        return at_sheet + rx / rz * kBackdrop;
    };
    // The lamp's x grows with the pixel across the sheet: bisect for the edge.
    double lo = 0.0;
    double hi = kWidth;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (lamp_x(mid, x0) < kEdge ? lo : hi) = mid;
    }
    lamp_x(lo, x0);
    return lo;
}

// The scene: the sheet (texture-mapped, one cell, the given element) before the lamp.
fs::path write_edge_scene(const TempDir& dir, double curvature) {
    dir.write("Attributes",
              "$ 2\n$ 1 1 1 2 2 0 0 0 0 1 1.5 0 0 0 0 1 glass\n"
              "$ 1 1 1 2 2 1 0 0 0 0 1 0 0 0 0 2 lamp\n");
    dir.write("lamp", rectangle(-50, -50, kEdge, 50, kBackdrop));
    // Row 0 at the top: u along +x, v along -y, so the outward side u x v faces the eye (-z).
    dir.write("sheet",
              fmt::format("1 1\n{0} 1 0\n{1} 1 0\n{0} -1 0\n{1} -1 0\n", -kHalfSheet, kHalfSheet));
    // The optical centre in the middle; the cylinder's axis along v (90 degrees).
    dir.write("prescription", fmt::format("1 1\ncentre 0.5 0.5\n0 0 {} 90 1 1 1\n", curvature));
    return dir.write("edge.scn",
                     fmt::format("$ 0 0 0 0 0 .5 3 0\n$ 0 0 {} 0 0 0\n$ 1\n$ {} 0.1\n$ 1\n"
                                 "$ {} 1\n$ 0 0 {} 0\n$ Attributes\n$ 1\n$ 1\n"
                                 "$ 1 2 0 lamp 1 0 0 0 0 0 0\n"
                                 "$ 1\n$ 1 sheet prescription 1 0 0 0 0 0 0 1 1\n",
                                 -kEyeDistance, 2 * kHalfAngle, kWidth, kWidth - 1));
}

// How many pixels of the row, from the left, see the lamp.
int lit_pixels(const std::vector<float>& row) {
    int lit = 0;
    while (lit < kWidth && row[static_cast<std::size_t>(3 * lit + 1)] > 0.5f) {
        ++lit;
    }
    for (int k = lit; k < kWidth; ++k) {
        EXPECT_EQ(row[static_cast<std::size_t>(3 * k + 1)], 0.0f) << "pixel " << k;
    }
    return lit;
}

// Pixel k sees the lamp when its centre, k + 0.5, is left of the edge: exactly the pixels whose
// centres lie left of the predicted edge must be lit. So the edge is placed to within a pixel
// (0.018 in the sheet's plane, 0.03 on the lamp); a prediction within 0.01 pixel of a centre would
// be too close to call, and is refused.
void expect_lit_up_to(const std::vector<float>& row, double edge) {
    const double centres_left = edge - 0.5;
    ASSERT_GT(std::fabs(centres_left - std::round(centres_left)), 0.01);
    EXPECT_EQ(lit_pixels(row), static_cast<int>(std::ceil(centres_left)));
}

TEST(TextureMapping, ACylinderDisplacesAnEdgeAsSnellsLawPredicts) {
    double flat_x0 = 0.0;
    const double flat = predicted_edge(0.0, flat_x0);
    for (const double k : {0.1, -0.1}) {
        SCOPED_TRACE(fmt::format("curvature {}", k));
        const TempDir dir;
        double x0 = 0.0;
        const double edge = predicted_edge(k, x0);
        ASSERT_LT(std::fabs(x0), kHalfSheet - 0.5) << "the edge must be seen through the sheet";
        // The prescription moves the edge by many pixels: a converging (convex) sheet shows it
        // further right, a diverging one further left.
        EXPECT_GT(std::copysign(1.0, k) * (edge - flat), 15.0);
        const std::vector<float> row = render_file(write_edge_scene(dir, k), {"-V", "-Da"});
        ASSERT_EQ(row.size(), 3u * kWidth);
        expect_lit_up_to(row, edge);
    }
    // And a flat element leaves the edge where a flat sheet of glass puts it.
    const TempDir dir;
    const std::vector<float> row = render_file(write_edge_scene(dir, 0.0), {"-V", "-Da"});
    expect_lit_up_to(row, flat);
}

// ---- A flat, white prescription changes nothing ---------------------------------------------

constexpr int kPaneRows = 4;
constexpr int kPaneColumns = 6;

// The pane's grid points: a 3 x 2 rectangle in z = 0, slightly uneven so that no two cells are
// alike, row 0 at the top.
std::vector<Vec3> pane_points() {
    std::vector<Vec3> points;
    for (int r = 0; r <= kPaneRows; ++r) {
        for (int c = 0; c <= kPaneColumns; ++c) {
            points.push_back({-1.5 + 0.5 * c + 0.01 * r, 1.0 - 0.5 * r - 0.02 * c * c / 6.0, 0});
        }
    }
    return points;
}

// The same grid as a filetype-0 polygon file: the vertices in the grid's order, each cell's
// edges in its loop order (point (r, c), (r, c+1), (r+1, c+1), (r+1, c)), outward left to the
// loop (0 0 0).
std::string pane_as_polygon_file() {
    const std::vector<Vec3> points = pane_points();
    std::string text = fmt::format("{}\n", points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        text += fmt::format("{} {} {} {}\n", k, points[k].x, points[k].y, points[k].z);
    }
    const int cells = kPaneRows * kPaneColumns;
    text += fmt::format("{}\n", 4 * cells);
    std::string polygons = fmt::format("{}\n", cells);
    for (int r = 0; r < kPaneRows; ++r) {
        for (int c = 0; c < kPaneColumns; ++c) {
            const int cell = r * kPaneColumns + c;
            const int at = r * (kPaneColumns + 1) + c;
            const int loop[4] = {at, at + 1, at + kPaneColumns + 2, at + kPaneColumns + 1};
            for (int e = 0; e < 4; ++e) {
                text += fmt::format("{} {} {}\n", 4 * cell + e, loop[e], loop[(e + 1) % 4]);
            }
            polygons += fmt::format("{} 4 {} {} {} {} 0 0 0 0\n", cell, 4 * cell, 4 * cell + 1,
                                    4 * cell + 2, 4 * cell + 3);
        }
    }
    return text + polygons;
}

TEST(TextureMapping, AFlatWhitePrescriptionDrawsThePlainGridsPicture) {
    const TempDir dir;
    dir.write("Attributes",
              "$ 4\n$ 0.9 0.8 0.7 20 20 0 0.05 0.3 0.3 0.5 1.3 10 20 10 20 1 glossy glass\n"
              "$ 1 1 1 2 2 1 0 0 0 0 1 0 0 0 0 2 light\n"
              "$ 0.8 0.2 0.1 2 2 0 0.05 0.9 0 0 1 0 0 0 0 3 red\n"
              "$ 0.9 0.9 0.9 2 2 0 0.05 0.9 0 0 1 0 0 0 0 4 white\n");
    fs::copy_file(source_dir() / "scenes/checker8", dir.path() / "checker8");
    dir.write("light", rectangle(-1, -1, 1, 1, 0));
    std::string grid = fmt::format("{} {}\n", kPaneRows, kPaneColumns);
    for (const Vec3& p : pane_points()) {
        grid += fmt::format("{} {} {}\n", p.x, p.y, p.z);
    }
    dir.write("pane.grid", grid);
    std::string map = fmt::format("{} {}\ncentre 3 2\n", kPaneRows, kPaneColumns);
    for (int k = 0; k < kPaneRows * kPaneColumns; ++k) {
        map += "0 0 0 37 1 1 1\n";
    }
    dir.write("pane.map", map);
    dir.write("pane.plain", pane_as_polygon_file());
    // A light above, a checkered floor (attributes 3 and 4), the pane standing on it; seen with
    // distributed reflection and refraction and shadow feelers through the pane.
    const std::string common =
        "$ 0 2 1 3 0 .5 4 2\n$ 0 3 -8 0 0.5 0\n$ 1\n$ 50 38\n$ 2\n$ 48 36\n$ 0 0 47 35\n"
        "$ Attributes\n";
    const std::string floor_and_light =
        "$ 1\n$ 1 3 0 checker8 1.5 0 -1 0 0 0 0\n$ 1\n$ 1 2 0 light 0.5 1 4 -1 90 0 0\n";
    const fs::path mapped = dir.write("mapped.scn", common + "$ 2\n" + floor_and_light +
                                                        "$ 1\n"
                                                        "$ 1 pane.grid pane.map 1 0 "
                                                        "0.2 0.5 0 20 0 4 6\n");
    const fs::path plain =
        dir.write("plain.scn", common + "$ 3\n" + floor_and_light +
                                   "$ 1\n$ 1 1 0 pane.plain 1 0 0.2 0.5 0 20 0\n");
    const std::vector<float> with_map = render_file(mapped, {"-V"});
    const std::vector<float> without = render_file(plain, {});
    ASSERT_EQ(with_map.size(), without.size());
    ASSERT_TRUE(std::any_of(without.begin(), without.end(), [](float v) { return v > 0.05f; }));
    const auto differ = std::mismatch(with_map.begin(), with_map.end(), without.begin());
    EXPECT_TRUE(differ.first == with_map.end())
        << "first difference at float " << (differ.first - with_map.begin());
}

// ---- Pictures on the grid --------------------------------------------------------------------

// A 2 x 2 grid over [-1, 1]^2 in z = 0 facing the eye at (0, 0, -10): row 0 at the top (y = 1),
// u along +x, v along -y, so that the outward side u x v faces the eye. `map_lines` go into the
// texture map before its (flat, white) elements; the view is `pixels` a side, 0.15 wide a side at
// distance 1.
fs::path write_picture_scene(const TempDir& dir, const std::string& map_lines, int pixels,
                             int lghtick, const std::string& attribute) {
    dir.write("Attributes", "$ 2\n$ " + attribute + " 1\n$ 1 1 1 2 2 1 0 0 0 0 1 0 0 0 0 2\n");
    dir.write("sheet",
              "2 2\n-1 1 0\n0 1 0\n1 1 0\n-1 0 0\n0 0 0\n1 0 0\n-1 -1 0\n0 -1 0\n"
              "1 -1 0\n");
    dir.write("map", "2 2\ncentre 1 1\n" + map_lines +
                         "0 0 0 0 1 1 1\n0 0 0 0 1 1 1\n0 0 0 0 1 1 1\n0 0 0 0 1 1 1\n");
    // A tiny lamp off to the side, at (3, 0, -4), out of the view.
    dir.write("lamp", rectangle(-0.01, -0.01, 0.01, 0.01, 0));
    const double view = 2 * std::atan(0.15) * 180 / std::numbers::pi;
    return dir.write(
        "pictures.scn",
        fmt::format("$ 0 {} 0 0 0 .5 2 0\n$ 0 0 -10 0 0 0\n$ 1\n$ {} {}\n$ 1\n$ {} {}\n"
                    "$ 0 0 {} {}\n$ Attributes\n$ 1\n$ 1\n$ 1 2 0 lamp 1 3 0 -4 0 0 0\n"
                    "$ 1\n$ 1 sheet map 1 0 0 0 0 0 0 2 2\n",
                    lghtick, view, view, pixels, pixels, pixels - 1, pixels - 1));
}

TEST(TextureMapping, AColourMapLiesOnTheGridAsItsRowsAndColumns) {
    // 8 x 8 pixels: red, green on top; blue, white below. An ambient-only white surface shows
    // the picture's colours themselves, bytes over 255.
    Image8 picture{8, 8, {}};
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            const bool right = x >= 4;
            const bool low = y >= 4;
            const std::uint8_t r = !low ? (right ? 0 : 255) : (right ? 255 : 0);
            const std::uint8_t g = !low ? (right ? 255 : 0) : (right ? 255 : 0);
            const std::uint8_t b = low ? 255 : 0;
            picture.rgb.insert(picture.rgb.end(), {r, g, b});
        }
    }
    const TempDir dir;
    write_png(picture, dir.path() / "quarters.png");
    const fs::path scene = write_picture_scene(dir, "colour_map quarters.png\n", 30, 0,
                                               "1 1 1 2 2 0 1 0 0 0 1 0 0 0 0");
    const std::vector<float> film = render_file(scene, {"-V", "-Da"});
    ASSERT_EQ(film.size(), 3u * 30 * 30);
    const auto pixel = [&](int x, int y) {
        const std::size_t at = 3 * static_cast<std::size_t>(y * 30 + x);
        return Rgb{film[at], film[at + 1], film[at + 2]};
    };
    // Pixel 10 sees x (or y) = -0.45 on the sheet, a quarter of the way in: u = 0.55, picture
    // pixel 2.2, inside its block. Pixel 19 sees +0.45.
    EXPECT_EQ(pixel(10, 10), (Rgb{1, 0, 0}));
    EXPECT_EQ(pixel(19, 10), (Rgb{0, 1, 0}));
    EXPECT_EQ(pixel(10, 19), (Rgb{0, 0, 1}));
    EXPECT_EQ(pixel(19, 19), (Rgb{1, 1, 1}));
    EXPECT_EQ(pixel(0, 0), Rgb{});  // beyond the sheet
}

TEST(TextureMapping, ANormalMapTurnsTheDiffuseLightByLambertsLaw) {
    // One pixel, whose ray meets the sheet at the origin; a white, purely diffuse sheet lit by a
    // lamp of intensity 1 at (3, 0, -4), no attenuation: the pixel is cos of the angle between
    // the normal and the lamp. The normal map's one pixel (200, 90, 230) means
    // 2 * byte / 255 - 1 along u (+x), up the picture (-v, which is +y here) and the outward
    // normal (-z).
    const TempDir dir;
    write_png(Image8{1, 1, {200, 90, 230}}, dir.path() / "tilt.png");
    const std::string diffuse = "1 1 1 2 2 0 0 1 0 0 1 0 0 0 0";
    const Vec3 to_lamp = normalize(Vec3{3, 0, -4});
    const auto channel = [](int byte) { return 2.0 * byte / 255.0 - 1.0; };
    const Vec3 mapped = normalize(Vec3{channel(200), channel(90), -channel(230)});
    const std::vector<float> flat =
        render_file(write_picture_scene(dir, "", 1, 2, diffuse), {"-V", "-Da", "-Dl"});
    const std::vector<float> bumped = render_file(
        write_picture_scene(dir, "normal_map tilt.png\n", 1, 2, diffuse), {"-V", "-Da", "-Dl"});
    ASSERT_EQ(flat.size(), 3u);
    ASSERT_EQ(bumped.size(), 3u);
    EXPECT_NEAR(flat[1], dot(Vec3{0, 0, -1}, to_lamp), 1e-6);
    EXPECT_NEAR(bumped[1], dot(mapped, to_lamp), 1e-6);
    EXPECT_GT(std::fabs(bumped[1] - flat[1]), 0.1);
}

}  // namespace
}  // namespace rt::test
