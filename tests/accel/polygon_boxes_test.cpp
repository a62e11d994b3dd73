// The bounding-box look before the exact test: its SSE2 form gives the plain form's answers, and
// neither ever skips a box the line passes through.
#include "rt/accel/voxel/polygon_boxes.h"

#include <array>
#include <random>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace rt
