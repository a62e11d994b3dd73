// The looks before the exact test: the bounding box's SSE2 form gives the plain form's answers,
// and neither ever skips a box the line passes through; the float triangle look gives the BVH
// packet test's answers (that it never skips a hit polygon: cell_packets_test.cpp).
#include "rt/accel/voxel/polygon_boxes.h"

#include <array>
#include <random>

#include "rt/accel/bvh/packet_prefilter.h"
#include "rt/accel/float_prefilter/triangle_prefilter.h"
#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

Ray random_ray(std::mt19937& rng) {
    std::normal_distribution<double> normal(0.0, 1.0);
    return Ray{{normal(rng), normal(rng), normal(rng)}, {normal(rng), normal(rng), normal(rng)}};
}

// A box around a point of the line (half the time) or anywhere near it, as floats.
std::array<float, 6> random_box(std::mt19937& rng, const Ray& ray, bool around_the_line) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    const Vec3 centre = around_the_line ? ray.at(4.0 * unit(rng) - 2.0)
                                        : Vec3{normal(rng), normal(rng), normal(rng)};
    std::array<float, 6> box{};
    for (int a = 0; a < 3; ++a) {
        // Sizes from 1e-6 to 1: thin boxes test the rounding at the slab edges.
        const double half = std::pow(10.0, -6.0 * unit(rng));
        box[a] = static_cast<float>(centre[a] - half);
        box[3 + a] = static_cast<float>(centre[a] + half);
    }
    return box;
}

TEST(PolygonBoxes, Sse2FormGivesThePlainFormsAnswers) {
#if defined(__SSE2__)
    std::mt19937 rng(21);
    int met = 0;
    for (int i = 0; i < 100000; ++i) {
        const Ray ray = random_ray(rng);
        const LineProbe line(ray);
        ASSERT_FALSE(line.any_parallel);
        const std::array<float, 6> box = random_box(rng, ray, i % 2 == 0);
        const bool plain = line_may_meet_box_plain(line, box.data());
        ASSERT_EQ(line_may_meet_box_sse2(line, box.data()), plain) << "case " << i;
        met += plain ? 1 : 0;
    }
    // Both answers occur often enough for the comparison to mean something.
    EXPECT_GT(met, 40000);
    EXPECT_LT(met, 90000);
#else
    GTEST_SKIP() << "no SSE2 on this machine";
#endif
}

TEST(PolygonBoxes, NeverSkipsABoxAroundAPointOfTheLine) {
    std::mt19937 rng(22);
    for (int i = 0; i < 100000; ++i) {
        Ray ray = random_ray(rng);
        if (i % 4 == 0) {
            ray.direction[i % 3] = 0.0;  // the plain form's parallel case
        }
        const LineProbe line(ray);
        const std::array<float, 6> box = random_box(rng, ray, true);
        ASSERT_TRUE(line_may_meet_box(line, box.data())) << "case " << i;
    }
}

// Triangles of every size from 1e-6 to 10, near the origin or far off, some long and thin.
Scene random_triangles(std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    test::SceneBuilder b;
    for (int i = 0; i < count; ++i) {
        const Vec3 centre =
            Vec3{normal(rng), normal(rng), normal(rng)} * (i % 5 == 0 ? 100.0 : 1.0);
        const double size = std::pow(10.0, 1.0 - 7.0 * unit(rng));
        std::vector<Vec3> corners;
        for (int v = 0; v < 3; ++v) {
            const double stretch = (i % 7 == 0 && v == 1) ? 50.0 : 1.0;
            corners.push_back(centre +
                              Vec3{normal(rng), normal(rng), normal(rng)} * (size * stretch));
        }
        b.add_polygon(corners);
    }
    b.add_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});  // a quad: never skipped
    return std::move(b.scene());
}

TEST(TriangleLook, GivesThePacketTestsAnswer) {
    std::mt19937 rng(23);
    const Scene scene = random_triangles(rng, 4000);
    const PolygonBoxes boxes(scene, 0.0);
    int candidates = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = random_ray(rng);
        const FloatRay float_ray(ray, boxes.scale());
        ASSERT_TRUE(float_ray.usable);
        bvh::TrianglePacket packet{};
        float corners[4][9];
        for (int lane = 0; lane < 4; ++lane) {
            const Polygon& p = scene.polygons[rng() % (scene.polygons.size() - 1)];
            for (int v = 0; v < 3; ++v) {
                const Vec3 c = scene.corner_position(p, v);
                for (int a = 0; a < 3; ++a) {
                    packet.corner[v][a][lane] = static_cast<float>(c[a]);
                    corners[lane][3 * v + a] = static_cast<float>(c[a]);
                }
            }
        }
        const int bits = bvh::packet_candidates(packet, float_ray);
        for (int lane = 0; lane < 4; ++lane) {
            const bool one = triangle_candidate(corners[lane], float_ray);
            ASSERT_EQ(one, ((bits >> lane) & 1) != 0) << "case " << i << " lane " << lane;
            candidates += one ? 1 : 0;
        }
    }
    EXPECT_GT(candidates, 0);
}

}  // namespace
}  // namespace rt
