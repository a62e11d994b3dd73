// One split of the BVH's build against what it must hold whatever its tuning: the references are a
// permutation of the range's, each side's boxes and counts are those of its references (the
// partition grows the sides' boxes of centres as it goes, the bins carry the rest), the sides do
// not overlap along some axis, and the same input gives the same order whatever the thread count.
#include "rt/accel/bvh/sah_split.h"

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace rt::bvh {
namespace {

// Random boxes: small triangles anywhere in a unit cube (a soup, where each reference's side is a
// coin toss), or strung along a line (a mesh in order, where neighbours go to the same side).
std::vector<PolygonReference> make_references(std::uint32_t count, bool in_order,
                                              std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<PolygonReference> refs(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        PolygonReference& r = refs[i];
        for (int k = 0; k < 3; ++k) {
            const float along = static_cast<float>(i) / static_cast<float>(count);
            const float at = in_order ? along + 0.01f * unit(random) : unit(random);
            r.box.lo[k] = at;
            r.box.hi[k] = at + 0.02f * unit(random);
        }
        r.polygon = i;
        r.triangles = 1 + i % 3;
    }
    return refs;
}

bool same_box(const Box& a, const Box& b) {
    return std::equal(a.lo, a.lo + 3, b.lo) && std::equal(a.hi, a.hi + 3, b.hi);
}

void expect_side_matches_its_references(const std::vector<PolygonReference>& refs,
                                        const ReferenceRange& side) {
    const ReferenceRange recomputed = make_range(refs, side.begin, side.end);
    EXPECT_TRUE(same_box(side.box, recomputed.box));
    EXPECT_TRUE(same_box(side.centroids, recomputed.centroids));
    EXPECT_EQ(side.triangles, recomputed.triangles);
}

// Some axis has every left centre at or below every right centre: the bins are monotone.
bool sides_apart_on_some_axis(const SplitDecision& split) {
    for (int k = 0; k < 3; ++k) {
        if (split.left.centroids.hi[k] <= split.right.centroids.lo[k]) {
            return true;
        }
    }
    return false;
}

void check_split(std::uint32_t count, bool in_order, std::uint32_t seed) {
    SCOPED_TRACE(testing::Message() << count << (in_order ? " in order" : " soup"));
    const std::vector<PolygonReference> original = make_references(count, in_order, seed);
    std::vector<PolygonReference> refs = original;
    const ReferenceRange whole = make_range(refs, 0, count);
    const SplitDecision split = split_range(refs, whole, false);
    ASSERT_FALSE(split.leaf);
    EXPECT_EQ(split.left.begin, 0u);
    EXPECT_EQ(split.left.end, split.right.begin);
    EXPECT_EQ(split.right.end, count);
    EXPECT_GT(split.left.size(), 0u);
    EXPECT_GT(split.right.size(), 0u);
    expect_side_matches_its_references(refs, split.left);
    expect_side_matches_its_references(refs, split.right);
    EXPECT_TRUE(sides_apart_on_some_axis(split));

    std::vector<std::uint32_t> before;
    std::vector<std::uint32_t> after;
    for (std::uint32_t i = 0; i < count; ++i) {
        before.push_back(original[i].polygon);
        after.push_back(refs[i].polygon);
    }
    std::sort(after.begin(), after.end());
    EXPECT_EQ(before, after);  // a permutation: nothing lost, nothing twice

    // Binned on four threads (ranges this big), the same split and the same order.
    std::vector<PolygonReference> again = original;
    const SplitDecision threaded = split_range(again, whole, false, 4);
    EXPECT_EQ(threaded.left.end, split.left.end);
    for (std::uint32_t i = 0; i < count; ++i) {
        ASSERT_EQ(again[i].polygon, refs[i].polygon) << i;
    }
}

TEST(SahSplit, SidesHoldTheirReferencesAndBoxes) {
    // Sizes around the partition's blocks (two blocks of 32 are partitioned the plain way), and
    // one big enough to be binned by several threads.
    for (const std::uint32_t count : {9u, 63u, 64u, 65u, 97u, 1000u, 4099u, 300000u}) {
        check_split(count, false, count);
        check_split(count, true, count + 1);
    }
}

}  // namespace
}  // namespace rt::bvh
