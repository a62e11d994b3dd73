// Mean value coordinates and the shading normals interpolated with them.
#include "rt/geometry/normals.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr Vec3 kUp{0, 0, 1};

std::vector<double> weights_at(const std::vector<Vec3>& corners, const Vec3& point,
                               const Vec3& normal = kUp) {
    std::vector<double> w(corners.size(), -7.0);
    mean_value_weights(corners, normal, point, w);
    return w;
}

Vec3 blend(const std::vector<Vec3>& corners, const std::vector<double>& w) {
    Vec3 sum;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        sum += corners[k] * w[k];
    }
    return sum;
}

double sum_of(const std::vector<double>& w) {
    return std::accumulate(w.begin(), w.end(), 0.0);
}

const std::vector<Vec3> triangle_corners{{0, 0, 0}, {4, 0, 0}, {0, 3, 0}};
const std::vector<Vec3> square_corners{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
const std::vector<Vec3> l_shape_corners{{0, 0, 0}, {2, 0, 0}, {2, 1, 0},
                                        {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};

std::vector<Vec3> star(int points, double outer, double inner) {
    std::vector<Vec3> loop;
    for (int k = 0; k < 2 * points; ++k) {
        const double phi = std::numbers::pi * k / points;
        const double r = k % 2 == 0 ? outer : inner;
        loop.push_back({r * std::cos(phi), r * std::sin(phi), 0.0});
    }
    return loop;
}

TEST(MeanValueWeights, AreBarycentricOnATriangle) {
    const std::vector<double> w = weights_at(triangle_corners, {1.0, 1.5, 0});
    // Barycentric coordinates of (1, 1.5): (1 - 1/4 - 1.5/3, 1/4, 1.5/3).
    EXPECT_NEAR(w[0], 0.25, 1e-12);
    EXPECT_NEAR(w[1], 0.25, 1e-12);
    EXPECT_NEAR(w[2], 0.5, 1e-12);
}

// Even-odd crossings: the reference for which random points are inside a simple polygon.
bool inside_by_crossings(const std::vector<Vec3>& loop, const Vec3& p) {
    bool inside = false;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const Vec3& a = loop[i];
        const Vec3& b = loop[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
            inside = !inside;
        }
    }
    return inside;
}

TEST(MeanValueWeights, SumToOneAndReproduceThePointInConvexAndConcavePolygons) {
    std::mt19937_64 random(41);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
    const std::vector<std::vector<Vec3>> polygons{triangle_corners, square_corners, l_shape_corners,
                                                  star(5, 2.0, 0.6), star(12, 3.0, 2.5)};
    for (const std::vector<Vec3>& polygon : polygons) {
        int inside = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 point{coordinate(random), coordinate(random), 0};
            if (!inside_by_crossings(polygon, point)) {
                continue;
            }
            ++inside;
            const std::vector<double> w = weights_at(polygon, point);
            ASSERT_NEAR(sum_of(w), 1.0, 1e-12);
            ASSERT_NEAR(length(blend(polygon, w) - point), 0.0, 1e-11) << point.x << "," << point.y;
        }
        EXPECT_GT(inside, 50);
    }
}

TEST(MeanValueWeights, ReproduceLinearFunctionsInsideConcavePolygons) {
    // Sample inside the L and a star, where some weights are negative; a linear function
    // f(p) = 3x - 2y + 1 must come back exactly from its corner values.
    const auto f = [](const Vec3& p) { return 3.0 * p.x - 2.0 * p.y + 1.0; };
    const std::vector<Vec3> points{{0.5, 0.5, 0}, {1.5, 0.3, 0}, {0.2, 1.9, 0}, {0.9, 0.9, 0}};
    for (const Vec3& p : points) {
        const std::vector<double> w = weights_at(l_shape_corners, p);
        double value = 0.0;
        for (std::size_t k = 0; k < l_shape_corners.size(); ++k) {
            value += w[k] * f(l_shape_corners[k]);
        }
        EXPECT_NEAR(value, f(p), 1e-12);
        EXPECT_NEAR(sum_of(w), 1.0, 1e-12);
    }
    // In a tip of a star, outside its kernel, some weights are negative and still reproduce it.
    const std::vector<Vec3> spiky = star(5, 2.0, 0.5);
    const Vec3 p{1.6, 0.05, 0};
    const std::vector<double> w = weights_at(spiky, p);
    EXPECT_NEAR(length(blend(spiky, w) - p), 0.0, 1e-12);
    EXPECT_LT(*std::min_element(w.begin(), w.end()), 0.0) << "a star has negative weights";
}

TEST(MeanValueWeights, OneAtACorner) {
    for (std::size_t k = 0; k < l_shape_corners.size(); ++k) {
        const std::vector<double> w = weights_at(l_shape_corners, l_shape_corners[k]);
        for (std::size_t j = 0; j < w.size(); ++j) {
            EXPECT_EQ(w[j], j == k ? 1.0 : 0.0) << "corner " << k << " weight " << j;
        }
    }
}

TEST(MeanValueWeights, LinearAlongAnEdge) {
    // A quarter of the way along the square's edge 1 -> 2.
    const std::vector<double> w = weights_at(square_corners, {2, 0.5, 0});
    EXPECT_NEAR(w[1], 0.75, 1e-12);
    EXPECT_NEAR(w[2], 0.25, 1e-12);
    EXPECT_EQ(w[0], 0.0);
    EXPECT_EQ(w[3], 0.0);
    // The closing edge 3 -> 0 too.
    const std::vector<double> closing = weights_at(square_corners, {0, 1.5, 0});
    EXPECT_NEAR(closing[3], 0.75, 1e-12);
    EXPECT_NEAR(closing[0], 0.25, 1e-12);
}

TEST(MeanValueWeights, SmoothAcrossTheInsideNearAnEdge) {
    // Just inside an edge the weights are close to the edge's.
    const std::vector<double> on = weights_at(l_shape_corners, {1.5, 1.0, 0});
    const std::vector<double> near = weights_at(l_shape_corners, {1.5, 1.0 - 1e-7, 0});
    for (std::size_t k = 0; k < on.size(); ++k) {
        EXPECT_NEAR(on[k], near[k], 1e-5);
    }
}

TEST(MeanValueWeights, IndependentOfOrientationAndPlane) {
    // The same polygon turned into a tilted plane gives the same weights.
    const double c = std::cos(0.4), s = std::sin(0.4);
    const auto tilt = [&](const Vec3& p) { return Vec3{p.x, c * p.y, s * p.y + 5.0}; };
    std::vector<Vec3> tilted;
    tilted.reserve(l_shape_corners.size());
    for (const Vec3& p : l_shape_corners) {
        tilted.push_back(tilt(p));
    }
    const Vec3 point{0.7, 1.3, 0};
    const std::vector<double> flat = weights_at(l_shape_corners, point);
    const std::vector<double> turned = weights_at(tilted, tilt(point), test::newell_normal(tilted));
    for (std::size_t k = 0; k < flat.size(); ++k) {
        EXPECT_NEAR(flat[k], turned[k], 1e-12);
    }
    // Reversing the loop and the normal together changes nothing either.
    std::vector<Vec3> reversed(l_shape_corners.rbegin(), l_shape_corners.rend());
    const std::vector<double> back = weights_at(reversed, point, -kUp);
    for (std::size_t k = 0; k < flat.size(); ++k) {
        EXPECT_NEAR(flat[k], back[flat.size() - 1 - k], 1e-12);
    }
}

TEST(MeanValueWeights, EqualWeightsForADegeneratePolygon) {
    const std::vector<Vec3> collapsed{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
    const std::vector<double> w = weights_at(collapsed, {0, 0, 0});
    for (const double x : w) {
        EXPECT_NEAR(x, 1.0 / 3.0, 1e-15);
    }
}

TEST(MeanValueWeights, WritesOnlyTheCornersWeightsAndRefusesShortSpans) {
    std::vector<double> w(6, -7.0);
    mean_value_weights(triangle_corners, kUp, {1, 1, 0}, w);
    EXPECT_EQ(w[3], -7.0);
    EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-12);
    std::vector<double> too_short(2, -7.0);
    mean_value_weights(triangle_corners, kUp, {1, 1, 0}, too_short);
    EXPECT_EQ(too_short[0], -7.0);
}

TEST(MeanValueWeights, ManyCornersNeedNoFixedLimit) {
    const std::vector<Vec3> many = star(40, 2.0, 1.5);  // 80 corners: past any inline buffer
    const Vec3 p{0.2, -0.3, 0};
    const std::vector<double> w = weights_at(many, p);
    EXPECT_NEAR(sum_of(w), 1.0, 1e-12);
    EXPECT_NEAR(length(blend(many, w) - p), 0.0, 1e-12);
}

TEST(InterpolatedNormal, EqualsTheVertexNormalAtACornerAndBlendsBetween) {
    Scene sphere = test::make_sphere({0, 0, 0}, 2.0, 6, 8, false);
    test::SceneBuilder rebuilt;  // (make_sphere has no vertex normals to smooth yet)
    for (std::uint32_t id = 0; id < sphere.polygons.size(); ++id) {
        std::vector<Vec3> loop;
        for (std::uint32_t k = 0; k < sphere.polygons[id].corner_count; ++k) {
            loop.push_back(sphere.corner_position(sphere.polygons[id], k));
        }
        rebuilt.add_polygon(loop, sphere.polygons[id].normal);
    }
    rebuilt.smooth_vertex_normals();
    const Scene& smooth = rebuilt.scene();
    for (std::uint32_t id = 0; id < smooth.polygons.size(); ++id) {
        const Polygon& p = smooth.polygons[id];
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 corner = smooth.corner_position(p, k);
            const Vec3 n =
                interpolated_normal(smooth.polygon_view(id), smooth.normals_of(id), corner);
            EXPECT_NEAR(length(n - smooth.vertex_normals[smooth.corners[p.first_corner + k]]), 0.0,
                        1e-12);
        }
        // In the middle: unit length and close to the outward radial direction.
        Vec3 middle;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            middle += smooth.corner_position(p, k) / p.corner_count;
        }
        const Vec3 n = interpolated_normal(smooth.polygon_view(id), smooth.normals_of(id), middle);
        EXPECT_NEAR(length(n), 1.0, 1e-12);
        EXPECT_GT(dot(n, normalize(middle)), 0.97);
    }
}

TEST(InterpolatedNormal, NeighboursAgreeOnTheirSharedEdge) {
    test::SceneBuilder b;
    const Vec3 a{0, 0, 0}, c{0, 2, 0};
    b.add_polygon({a, {2, 0, 0.5}, {2, 2, 0.3}, c}, kUp);
    b.add_polygon({a, c, {-2, 2, 0.7}, {-2, 0, 0.2}}, kUp);
    b.smooth_vertex_normals();
    for (const double y : {0.1, 0.7, 1.3, 1.9}) {
        const Vec3 on_edge{0, y, 0};
        EXPECT_NEAR(
            length(
                interpolated_normal(b.scene().polygon_view(0), b.scene().normals_of(0), on_edge) -
                interpolated_normal(b.scene().polygon_view(1), b.scene().normals_of(1), on_edge)),
            0.0, 1e-12);
    }
}

TEST(InterpolatedNormal, PolygonNormalWithoutVertexNormals) {
    Scene box = test::make_box({0, 0, 0}, {1, 1, 1}, false);
    box.vertex_normals.clear();
    EXPECT_EQ(interpolated_normal(box.polygon_view(0), box.normals_of(0), {0.5, 0.5, 0}),
              box.polygons[0].normal);
}

TEST(InterpolatedNormal, PolygonNormalWhereVertexNormalsCancel) {
    test::SceneBuilder b;
    b.add_polygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, kUp);
    Scene& s = b.scene();
    s.vertex_normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}, {0, 0, -1}};  // cancel at the centre
    EXPECT_EQ(interpolated_normal(s.polygon_view(0), s.normals_of(0), {1, 1, 0}),
              s.polygons[0].normal);
}

TEST(PolygonWeights, MatchTheSpanForm) {
    const Scene box = test::make_box({0, 0, 0}, {2, 2, 2}, false);
    const Polygon& p = box.polygons[2];
    std::vector<Vec3> loop;
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        loop.push_back(box.corner_position(p, k));
    }
    const Vec3 point = (loop[0] * 0.2 + loop[1] * 0.3 + loop[2] * 0.5);
    std::vector<double> from_scene(4), from_span(4);
    polygon_weights(box.polygon_view(2), point, from_scene);
    mean_value_weights(loop, p.normal, point, from_span);
    EXPECT_EQ(from_scene, from_span);
}

}  // namespace
}  // namespace rt
