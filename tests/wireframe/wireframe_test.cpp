// The wireframe of a small scene against projections worked out here from the manual's camera
// (docs/rendering.md): lines where the polygons' edges project, green normals from their centres,
// the octree's boxes with -oo, nothing elsewhere, and the same lines whatever the window.
#include "rt/wireframe/wireframe.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rt/accel/octree/octree_tree.h"
#include "rt/wireframe/wire_segments.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

struct Point {
    double x = 0.0;
    double y = 0.0;
};

// The manual's camera by hand: the eye looks at the look point, +y up, +x right with z into the
// screen, view angles the full angles of the view area.
Point project_by_hand(const SceneView& v, const Vec3& p) {
    const Vec3 forward = normalize(v.look - v.eye);
    const Vec3 right = normalize(cross(Vec3{0.0, 1.0, 0.0}, forward));
    const Vec3 up = cross(forward, right);
    const Vec3 d = p - v.eye;
    const double depth = dot(d, forward);
    const double to_radians = std::numbers::pi / 180.0;
    const double sx = dot(d, right) / depth / std::tan(0.5 * v.view_angle_x_degrees * to_radians);
    const double sy = dot(d, up) / depth / std::tan(0.5 * v.view_angle_y_degrees * to_radians);
    return {(sx + 1.0) * 0.5 * v.width, (1.0 - sy) * 0.5 * v.height};
}

// A pixel drawn is one the line passes through: its centre is at most half a diagonal away.
const double kHalfDiagonal = std::sqrt(0.5) + 1e-9;

double distance_to(const Point& p, const Point& a, const Point& b) {
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    const double t =
        len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// A 4 x 3 rectangle facing the eye, seen from above and to the right, made of 6 x 4 quads (more
// than an octree leaf holds, so that the octree splits).
Scene rectangle_scene() {
    test::SceneBuilder builder;
    Scene& s = builder.scene();
    s.view.width = 96;
    s.view.height = 72;
    s.view.window = {0, 0, 95, 71};
    s.view.eye = {6.0, 3.0, -10.0};
    s.view.look = {0.0, 0.0, 0.0};
    s.view.screen_distance = 1.0;
    s.view.view_angle_x_degrees = 40.0;
    s.view.view_angle_y_degrees = 30.0;
    const double w = 4.0 / 6.0;
    const double h = 3.0 / 4.0;
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 4; ++j) {
            const double x = -2.0 + i * w;
            const double y = -1.5 + j * h;
            builder.add_polygon({{x, y, 0}, {x + w, y, 0}, {x + w, y + h, 0}, {x, y + h, 0}},
                                {0, 0, -1});
        }
    }
    return builder.scene();
}

std::vector<std::pair<Point, Point>> projected_edges(const Scene& scene) {
    std::vector<std::pair<Point, Point>> edges;
    for (const WireSegment& e : polygon_edges(scene)) {
        edges.emplace_back(project_by_hand(scene.view, e.from), project_by_hand(scene.view, e.to));
    }
    return edges;
}

bool is(const Rgb& v, const Rgb& colour) {
    return v.r == colour.r && v.g == colour.g && v.b == colour.b;
}

// The centres of the pixels drawn in `colour`.
std::vector<Point> pixels_of(const Film& film, const Rgb& colour) {
    std::vector<Point> centres;
    const PixelRect& w = film.window();
    for (int y = w.top; y <= w.bottom; ++y) {
        for (int x = w.left; x <= w.right; ++x) {
            if (is(film.pixel(x, y), colour)) {
                centres.push_back({x + 0.5, y + 0.5});
            }
        }
    }
    return centres;
}

double nearest_line(const Point& p, const std::vector<std::pair<Point, Point>>& lines) {
    double nearest = 1e9;
    for (const auto& [a, b] : lines) {
        nearest = std::min(nearest, distance_to(p, a, b));
    }
    return nearest;
}

Film full_film(const Scene& scene) {
    return Film(scene.view.width, scene.view.height, scene.view.window);
}

TEST(Wireframe, EdgesAreDrawnWhereTheyProjectAndNowhereElse) {
    const Scene scene = rectangle_scene();
    Film film = full_film(scene);
    draw_wireframe(scene, {}, film);
    EXPECT_TRUE(film.complete());
    const std::vector<std::pair<Point, Point>> edges = projected_edges(scene);
    const std::vector<Point> white = pixels_of(film, kWireEdgeColour);
    ASSERT_GT(white.size(), 60U);
    for (const Point& p : white) {
        EXPECT_LE(nearest_line(p, edges), kHalfDiagonal) << p.x << ", " << p.y;
    }
    // Every few tenths of a pixel along each edge, a drawn pixel within one pixel.
    for (const auto& [a, b] : edges) {
        for (double t = 0.0; t <= 1.0; t += 0.01) {
            const Point q{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
            EXPECT_TRUE(std::any_of(white.begin(), white.end(),
                                    [&](const Point& p) {
                                        return std::fabs(p.x - q.x) <= 1.0 &&
                                               std::fabs(p.y - q.y) <= 1.0;
                                    }))
                << q.x << ", " << q.y;
        }
    }
    // Nothing else is drawn: no normals without a length, no boxes without an octree.
    const std::size_t drawn = static_cast<std::size_t>(
        std::count_if(film.data().begin(), film.data().end(), [](float v) { return v != 0.0F; }));
    EXPECT_EQ(drawn, 3 * white.size());
}

TEST(Wireframe, NormalsAreGreenLinesFromTheCentresAlongTheNormal) {
    const Scene scene = rectangle_scene();
    Film film = full_film(scene);
    draw_wireframe(scene, {.normal_length = 3.0}, film);
    // From each quad's centre 3 units toward the eye (the outward normal is -z).
    std::vector<std::pair<Point, Point>> normal;
    for (const Polygon& p : scene.polygons) {
        Vec3 centre;
        for (std::uint32_t k = 0; k < 4; ++k) {
            centre += scene.corner_position(p, k) * 0.25;
        }
        normal.emplace_back(project_by_hand(scene.view, centre),
                            project_by_hand(scene.view, centre + Vec3{0, 0, -3}));
    }
    const std::vector<Point> green = pixels_of(film, kWireNormalColour);
    ASSERT_GE(green.size(), 24U * 3U);
    for (const Point& p : green) {
        EXPECT_LE(nearest_line(p, normal), kHalfDiagonal) << p.x << ", " << p.y;
    }
    Film none = full_film(scene);
    draw_wireframe(scene, {.normal_length = 0.0}, none);
    EXPECT_TRUE(pixels_of(none, kWireNormalColour).empty());
}

TEST(Wireframe, OctreeBoxesAddTheLeavesEdgesUnderThePolygons) {
    const Scene scene = rectangle_scene();
    OctreeBuildSettings build;
    build.depth = 1;
    const OctreeTree tree = build_octree_depth_first(scene, build);
    ASSERT_EQ(tree.nodes.size(), 9U);  // the root split once: 8 leaves
    Film plain = full_film(scene);
    draw_wireframe(scene, {}, plain);
    Film boxed = full_film(scene);
    draw_wireframe(scene, {.octree = &tree}, boxed);
    std::vector<std::pair<Point, Point>> box_edges;
    for (const WireSegment& e : octree_leaf_edges(tree)) {
        box_edges.emplace_back(project_by_hand(scene.view, e.from),
                               project_by_hand(scene.view, e.to));
    }
    ASSERT_EQ(box_edges.size(), 8U * 12U);
    const std::vector<Point> blue = pixels_of(boxed, kWireOctreeColour);
    EXPECT_GT(blue.size(), 100U);
    for (const Point& p : blue) {
        EXPECT_LE(nearest_line(p, box_edges), kHalfDiagonal) << p.x << ", " << p.y;
    }
    EXPECT_TRUE(pixels_of(plain, kWireOctreeColour).empty());
    // The polygons' edges are drawn over the boxes: the same white pixels either way.
    const std::vector<Point> white_plain = pixels_of(plain, kWireEdgeColour);
    const std::vector<Point> white_boxed = pixels_of(boxed, kWireEdgeColour);
    ASSERT_EQ(white_plain.size(), white_boxed.size());
    for (std::size_t i = 0; i < white_plain.size(); ++i) {
        EXPECT_EQ(white_plain[i].x, white_boxed[i].x);
        EXPECT_EQ(white_plain[i].y, white_boxed[i].y);
    }
}

TEST(Wireframe, AWindowShowsTheSameLinesAsTheWholeView) {
    const Scene scene = rectangle_scene();
    OctreeBuildSettings build;
    build.depth = 2;
    const OctreeTree tree = build_octree_depth_first(scene, build);
    Film whole = full_film(scene);
    draw_wireframe(scene, {.normal_length = 2.0, .octree = &tree}, whole);
    const PixelRect window{20, 10, 70, 45};
    Film part(scene.view.width, scene.view.height, window);
    draw_wireframe(scene, {.normal_length = 2.0, .octree = &tree}, part);
    EXPECT_TRUE(part.complete());
    int lit = 0;
    for (int y = window.top; y <= window.bottom; ++y) {
        for (int x = window.left; x <= window.right; ++x) {
            const Rgb a = whole.pixel(x, y);
            const Rgb b = part.pixel(x, y);
            EXPECT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b) << x << ", " << y;
            lit += a.g > 0.0 ? 1 : 0;
        }
    }
    EXPECT_GT(lit, 50);
}

}  // namespace
}  // namespace rt
