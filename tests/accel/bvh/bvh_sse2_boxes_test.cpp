// The BVH's SSE2 eight-box test, which the traversal uses on processors without AVX2 (so this
// machine's renders may never run it), against the slab test in double: it never rejects a box the
// ray's line meets within the t interval, rejects boxes clearly missed, never enters an empty
// slot, and reports entries no later than the exact ones.
#include <random>

#include "rt/accel/bvh/box_test.h"

#include <gtest/gtest.h>

#include "accel/bvh/random_wide_node.h"

namespace rt::bvh {
namespace {

using test::exact_slab;
using test::random_corner;
using test::random_point;
using test::random_wide_node;
using test::Slab;
using test::uniform;

constexpr double kSceneScale = 16.0;

TEST(BvhSse2Boxes, ConservativeAgainstTheExactSlabTest) {
    std::mt19937 rng(2024);
    int hits = 0;
    int clear_misses = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const WideNode node = random_wide_node(rng);
        const Vec3 origin{uniform(rng, -14, 14), uniform(rng, -14, 14), uniform(rng, -14, 14)};
        // Most rays aim at a point of one of the boxes, so that many boxes are met.
        const int aimed = static_cast<int>(rng() % 9);
        Vec3 direction{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
        if (aimed < 7) {
            for (int k = 0; k < 3; ++k) {
                direction[k] = uniform(rng, node.lo[k][aimed], node.hi[k][aimed]) - origin[k];
            }
        }
        if (length(direction) < 0.05) {
            continue;
        }
        direction = normalize(direction);
        const Ray ray{origin, direction};
        // Half the rays start their interval at the origin, half a little further on.
        const double t_min = trial % 2 == 0 ? 0.0 : uniform(rng, 0.0f, 10.0f);
        const double t_max = trial % 3 == 0 ? 1e30 : t_min + uniform(rng, 0.1f, 20.0f);
        const FloatRay fray(ray, kSceneScale);
        ASSERT_TRUE(fray.usable);
        const BoxRay box_ray(fray);
        WideHits out;
        test_wide_boxes_sse2(node, box_ray, simd::Float4::broadcast(fray.scaled_down(t_min)),
                             simd::Float4::broadcast(fray.scaled_up(t_max)), out);
        EXPECT_EQ(out.mask & 0x80, 0) << "the empty slot was entered";
        for (int c = 0; c < 7; ++c) {
            const Slab s = exact_slab(node, c, ray);
            const bool meets = s.enter <= s.exit && s.exit >= t_min && s.enter <= t_max;
            const bool set = (out.mask >> c & 1) != 0;
            if (meets) {
                ++hits;
                EXPECT_TRUE(set) << "trial " << trial << " child " << c;
                EXPECT_LE(out.entry[c], s.enter * fray.scale_t) << "trial " << trial;
            }
            // Clearly missed: by more than a thousandth of the scene in t.
            const double slack = 1e-3 * kSceneScale;
            const bool clearly_missed =
                s.enter > s.exit + slack || s.exit < t_min - slack || s.enter > t_max + slack;
            if (clearly_missed) {
                ++clear_misses;
                EXPECT_FALSE(set) << "trial " << trial << " child " << c;
            }
        }
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(clear_misses, 2000);
}

// The tightest case for the margins: the line through a box's corner, from origins at the far side
// of the scene and beyond it, where a plane's t is largest against the margin. The test widens its
// interval by slab_margin alone, which covers the relative rounding of t (float_ray.cpp, part 2):
// the corner's box is kept, entered no later than the exact slab test says, and left no earlier.
TEST(BvhSse2Boxes, KeepsTheBoxWhoseCornerTheLineGrazesFarAway) {
    std::mt19937 rng(77);
    int kept = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const WideNode node = random_wide_node(rng);
        const int aimed = static_cast<int>(rng() % 7);
        const float reach = trial % 2 == 0 ? 14.0f : 1000.0f;
        const Vec3 origin = random_point(rng, reach);
        const Vec3 corner = random_corner(rng, node, aimed);
        const Vec3 direction = corner - origin;
        if (length(direction) < 0.05) {
            continue;
        }
        const Ray ray{origin, normalize(direction)};
        const FloatRay fray(ray, kSceneScale);
        ASSERT_TRUE(fray.usable);
        const Slab s = exact_slab(node, aimed, ray);
        if (!(s.enter <= s.exit && s.exit >= 0.0)) {
            continue;  // the corner is behind the origin, or rounding put the line just outside
        }
        // The interval ends exactly where the line meets the corner.
        const double t_corner = length(direction);
        const BoxRay box_ray(fray);
        WideHits out;
        test_wide_boxes_sse2(node, box_ray, simd::Float4::broadcast(fray.scaled_down(t_corner)),
                             simd::Float4::broadcast(fray.scaled_up(t_corner)), out);
        ASSERT_TRUE((out.mask >> aimed & 1) != 0) << "trial " << trial;
        EXPECT_LE(out.entry[aimed], s.enter * fray.scale_t) << "trial " << trial;
        ++kept;
    }
    EXPECT_GT(kept, 10000);
}

}  // namespace
}  // namespace rt::bvh
