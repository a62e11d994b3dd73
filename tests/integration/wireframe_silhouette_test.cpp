// The wireframe lies on the ray-traced picture: the cube of scenes/twocubes, its corners projected
// as -w projects them, against the corners of the cube's silhouette found in the picture the
// renderer draws of it. The silhouette is measured in the picture alone: the cube is rendered by
// itself (the checkerboard and the light left out, so every pixel that sees the cube is lit by its
// ambient light and every other pixel is black); the hull of the lit pixels says roughly where
// each side runs, each side is then fitted to where the picture turns from black to lit across
// it, and the corners are where neighbouring sides meet.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/core/diagnostics.h"
#include "rt/image/gro_format.h"
#include "rt/render/renderer.h"
#include "rt/scene/read/load_scene.h"
#include "rt/wireframe/line_projection.h"
#include "rt/wireframe/wireframe.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

struct Point {
    double x = 0.0;
    double y = 0.0;
};

double cross(const Point& o, const Point& a, const Point& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double distance(const Point& a, const Point& b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

// Andrew's monotone chain: the hull's corners in order, collinear points dropped.
std::vector<Point> convex_hull(std::vector<Point> points) {
    std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    std::vector<Point> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) {
            --k;
        }
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) {
            --k;
        }
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

double direction_of(const Point& a, const Point& b) {
    return std::atan2(b.y - a.y, b.x - a.x);
}

double turn_between(double from, double to) {
    const double pi = std::acos(-1.0);
    double d = to - from;
    while (d > pi) {
        d -= 2 * pi;
    }
    while (d <= -pi) {
        d += 2 * pi;
    }
    return std::fabs(d);
}

std::optional<Point> meet(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
    if (std::fabs(den) < 1e-12) {
        return std::nullopt;
    }
    const double t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) * (d.x - c.x)) / den;
    return Point{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

// The pixels that see the cube.
struct Mask {
    int width = 0;
    int height = 0;
    std::vector<char> lit;
    bool at(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height &&
               lit[static_cast<std::size_t>(y * width + x)] != 0;
    }
};

struct Line {
    Point from;
    Point to;
};

// The silhouette's sides, roughly: along a straight side the hull of the lit pixels' centres runs
// through the lattice points nearest it, so its long edges point along the side; those within
// kSameSide of each other in a row make one side.
std::vector<Line> rough_sides(const std::vector<Point>& hull) {
    constexpr double kLongEdge = 6.0;                       // pixels
    const double kSameSide = 12.0 * std::acos(-1.0) / 180;  // radians
    std::vector<Line> sides;
    double direction = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const Point& a = hull[i];
        const Point& b = hull[(i + 1) % hull.size()];
        if (distance(a, b) < kLongEdge) {
            continue;
        }
        const double d = direction_of(a, b);
        if (!sides.empty() && turn_between(direction, d) < kSameSide) {
            sides.back().to = b;
        } else {
            sides.push_back({a, b});
            direction = d;
        }
    }
    if (sides.size() > 1 &&
        turn_between(direction_of(sides.back().from, sides.back().to),
                     direction_of(sides.front().from, sides.front().to)) < kSameSide) {
        sides.front().from = sides.back().from;  // the first side began mid-way
        sides.pop_back();
    }
    return sides;
}

// A side measured where the picture changes: across the middle of the side, on each row (a
// steep side) or column, the last lit pixel outward, and the edge half a pixel beyond its
// centre; a least-squares line through those crossings (each off by at most half a pixel, and
// many of them).
Line refined(const Line& side, const Mask& mask, const Point& inside) {
    const double dx = side.to.x - side.from.x;
    const double dy = side.to.y - side.from.y;
    const bool steep = std::fabs(dy) > std::fabs(dx);
    // Outward: away from a point inside the silhouette.
    const Point middle{(side.from.x + side.to.x) / 2, (side.from.y + side.to.y) / 2};
    const int outward = steep ? (middle.x > inside.x ? 1 : -1) : (middle.y > inside.y ? 1 : -1);
    const double lo = std::min(steep ? side.from.y : side.from.x, steep ? side.to.y : side.to.x);
    const double hi = std::max(steep ? side.from.y : side.from.x, steep ? side.to.y : side.to.x);
    const double margin = 0.15 * (hi - lo);
    std::vector<Point> crossings;  // (along, across)
    for (int k = static_cast<int>(lo + margin); k <= static_cast<int>(hi - margin); ++k) {
        const int extent = steep ? mask.width : mask.height;
        int last = -1;
        for (int j = 0; j < extent; ++j) {
            const int probe = outward > 0 ? j : extent - 1 - j;
            if (steep ? mask.at(probe, k) : mask.at(k, probe)) {
                last = probe;
            }
        }
        if (last >= 0) {
            crossings.push_back({k + 0.5, last + 0.5 + 0.5 * outward});
        }
    }
    // across = a + b * along
    double sa = 0, sc = 0, saa = 0, sac = 0;
    for (const Point& c : crossings) {
        sa += c.x;
        sc += c.y;
        saa += c.x * c.x;
        sac += c.x * c.y;
    }
    const double n = static_cast<double>(crossings.size());
    const double b = (n * sac - sa * sc) / (n * saa - sa * sa);
    const double a = (sc - b * sa) / n;
    const auto point = [&](double along) {
        const double across = a + b * along;
        return steep ? Point{across, along} : Point{along, across};
    };
    return {point(lo), point(hi)};
}

// The silhouette's corners: where neighbouring measured sides meet.
std::vector<Point> silhouette_corners(const Mask& mask) {
    std::vector<Point> centres;
    Point inside;
    for (int y = 0; y < mask.height; ++y) {
        for (int x = 0; x < mask.width; ++x) {
            if (mask.at(x, y)) {
                centres.push_back({x + 0.5, y + 0.5});
                inside.x += x + 0.5;
                inside.y += y + 0.5;
            }
        }
    }
    inside.x /= static_cast<double>(centres.size());
    inside.y /= static_cast<double>(centres.size());
    std::vector<Line> sides = rough_sides(convex_hull(centres));
    for (Line& side : sides) {
        side = refined(side, mask, inside);
    }
    std::vector<Point> corners;
    for (std::size_t i = 0; i < sides.size(); ++i) {
        const Line& s = sides[i];
        const Line& next = sides[(i + 1) % sides.size()];
        if (const std::optional<Point> p = meet(s.from, s.to, next.from, next.to)) {
            corners.push_back(*p);
        }
    }
    return corners;
}

// scenes/twocubes with only its cube, the surface read from the file "cube".
Scene cube_of_twocubes() {
    Diagnostics quiet;
    Scene scene = load_scene(source_dir() / "scenes" / "twocubes.scn", ReaderDialect{}, quiet);
    std::vector<Polygon> polygons;
    std::vector<SourceRef> origins;
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
        if (scene.surfaces[scene.polygons[i].surface].file == "cube") {
            polygons.push_back(scene.polygons[i]);
            origins.push_back(scene.polygon_origin[i]);
        }
    }
    scene.polygons = polygons;
    scene.polygon_origin = origins;
    return scene;
}

std::vector<Vec3> cube_corners(const Scene& scene) {
    std::vector<Vec3> corners;
    for (const Polygon& p : scene.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 c = scene.corner_position(p, k);
            if (std::find(corners.begin(), corners.end(), c) == corners.end()) {
                corners.push_back(c);
            }
        }
    }
    return corners;
}

// The corners -w draws: the cube's corners through the wireframe's projection, wrapped in their
// hull (the silhouette of a convex solid is the hull of its projected corners).
std::vector<Point> projected_silhouette(const Scene& scene) {
    const LineProjection projection(scene.view.camera());
    std::vector<Point> points;
    for (const Vec3& c : cube_corners(scene)) {
        const std::optional<PixelPoint> p = projection.point(c);
        EXPECT_TRUE(p.has_value());
        if (p) {
            points.push_back({p->x, p->y});
        }
    }
    return convex_hull(points);
}

TEST(WireframeSilhouette, CubeCornersLandOnTheRenderedSilhouetteWithinOnePixel) {
    const Scene scene = cube_of_twocubes();
    ASSERT_EQ(scene.polygons.size(), 6U);
    ASSERT_EQ(cube_corners(scene).size(), 8U);

    const BruteForce accel(scene);
    RenderSettings settings;
    settings.window = scene.view.window;
    RenderObserver silent;
    RenderStatistics statistics;
    const Film film = render(scene, accel, settings, silent, statistics);
    Mask mask{film.view_width(), film.view_height(), {}};
    mask.lit.assign(static_cast<std::size_t>(mask.width * mask.height), 0);
    std::size_t lit = 0;
    for (int y = film.window().top; y <= film.window().bottom; ++y) {
        for (int x = film.window().left; x <= film.window().right; ++x) {
            const Rgb v = film.pixel(x, y);
            if (v.r + v.g + v.b > 0.0) {
                mask.lit[static_cast<std::size_t>(y * mask.width + x)] = 1;
                ++lit;
            }
        }
    }
    ASSERT_GT(lit, 1000U) << "the cube should cover thousands of pixels";
    const std::vector<Point> found = silhouette_corners(mask);
    const std::vector<Point> predicted = projected_silhouette(scene);
    ASSERT_EQ(found.size(), predicted.size()) << "the picture's silhouette has another shape";
    ASSERT_GE(predicted.size(), 4U);
    for (const Point& p : predicted) {
        double nearest = 1e9;
        for (const Point& f : found) {
            nearest = std::min(nearest, distance(p, f));
        }
        EXPECT_LE(nearest, 1.0) << fmt::format("projected corner ({:.2f}, {:.2f})", p.x, p.y);
    }
}

// rt -w itself draws those corners: an edge's pixel at each projected silhouette corner, or
// beside it (a line is drawn one pixel a column, where it crosses the column's centre).
TEST(WireframeSilhouette, RtDashWDrawsTheCubesCorners) {
    TempDir dir;
    const ProgramResult r = run_program("rt",
                                        {(source_dir() / "scenes" / "twocubes").string(), "-w",
                                         "--quiet", "--output", "w.gro", "-n"},
                                        dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Film film = read_gro(dir.path() / "w.gro");
    ASSERT_TRUE(film.complete());
    const auto is_edge = [&](int x, int y) {
        const Rgb v = film.pixel(x, y);
        return v.r == kWireEdgeColour.r && v.g == kWireEdgeColour.g && v.b == kWireEdgeColour.b;
    };
    for (const Point& p : projected_silhouette(cube_of_twocubes())) {
        const int x = static_cast<int>(p.x);
        const int y = static_cast<int>(p.y);
        bool drawn = false;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                drawn = drawn || is_edge(x + dx, y + dy);
            }
        }
        EXPECT_TRUE(drawn) << fmt::format("no edge at ({:.2f}, {:.2f})", p.x, p.y);
    }
}

}  // namespace
}  // namespace rt::test
