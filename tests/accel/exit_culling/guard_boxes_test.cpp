// The guards' boxes tested four at a time (guard_boxes.h) must answer as line_may_meet_box does
// for each box: lines through corners and along faces, boxes of no extent, huge and NaN planes,
// zero direction components, and only the asked guards reported.
#include "rt/accel/exit_culling/guard_boxes.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace rt::test {
namespace {

using Box = std::array<float, 6>;

// What GuardBoxes::met must give: line_may_meet_box box by box, for the asked ones.
std::uint32_t one_by_one(const LineProbe& line, const std::vector<Box>& boxes,
                         std::uint32_t asked) {
    std::uint32_t found = 0;
    for (std::size_t g = 0; g < boxes.size(); ++g) {
        if (((asked >> g) & 1u) != 0 && line_may_meet_box(line, boxes[g].data())) {
            found |= std::uint32_t{1} << g;
        }
    }
    return found;
}

// A coordinate from a small set of awkward values, or a random one in [-4, 4].
double coordinate(std::mt19937_64& random) {
    static const std::array<double, 9> awkward{0.0,
                                               -0.0,
                                               1.0,
                                               -1.0,
                                               0.5,
                                               1e-30,
                                               1e30,
                                               std::numeric_limits<double>::infinity(),
                                               std::numeric_limits<double>::quiet_NaN()};
    std::uniform_int_distribution<int> pick(0, 19);
    const int which = pick(random);
    if (which < static_cast<int>(awkward.size())) {
        return awkward[static_cast<std::size_t>(which)];
    }
    return std::uniform_real_distribution<double>(-4.0, 4.0)(random);
}

Box random_box(std::mt19937_64& random) {
    Box box{};
    for (int a = 0; a < 3; ++a) {
        const auto lo = static_cast<float>(coordinate(random));
        const auto hi = static_cast<float>(coordinate(random));
        // Mostly ordered boxes, some flat (lo == hi), some inverted or NaN as given.
        const bool order = std::uniform_int_distribution<int>(0, 3)(random) != 0;
        box[static_cast<std::size_t>(a)] = order && hi < lo ? hi : lo;
        box[static_cast<std::size_t>(a) + 3] = order && hi < lo ? lo : hi;
    }
    return box;
}

TEST(GuardBoxes, AnswerAsTheSingleBoxTestForEveryBox) {
    std::mt19937_64 random(15);
    int lines = 0;
    for (int round = 0; round < 400; ++round) {
        const int count = std::uniform_int_distribution<int>(1, 31)(random);
        std::vector<Box> boxes;
        boxes.reserve(static_cast<std::size_t>(count));
        for (int g = 0; g < count; ++g) {
            boxes.push_back(random_box(random));
        }
        GuardBoxes table;
        // Another polygon's guards first, so that this one's blocks do not start at 0.
        const std::vector<Box> before(5, random_box(random));
        table.add(before);
        const std::uint32_t first = table.add(boxes);
        EXPECT_EQ(first, 2u);
        for (int k = 0; k < 200; ++k) {
            Ray ray;
            ray.origin = {coordinate(random), coordinate(random), coordinate(random)};
            ray.direction = {coordinate(random), coordinate(random), coordinate(random)};
            if (!is_finite(ray.origin) || !is_finite(ray.direction)) {
                continue;  // LeavingTable::verdict asks only finite lines
            }
            const LineProbe line(ray);
            const std::uint32_t all = count == 32 ? ~0u : (std::uint32_t{1} << count) - 1u;
            const std::uint32_t asked =
                static_cast<std::uint32_t>(random()) & all & (k % 2 == 0 ? all : 0x0f0f0f0fu);
            ASSERT_EQ(table.met(line, first, asked), one_by_one(line, boxes, asked))
                << "round " << round << ", line " << k;
            ++lines;
        }
    }
    EXPECT_GT(lines, 10000);  // enough finite lines were asked
}

TEST(GuardBoxes, TellsLinesThroughCornersAndAlongFaces) {
    // A unit box, and its neighbours touching each face: lines along the shared faces and
    // through the shared corners are on the boundary of several boxes at once.
    std::vector<Box> boxes{{0, 0, 0, 1, 1, 1},  {1, 0, 0, 2, 1, 1},  {0, 1, 0, 1, 2, 1},
                           {0, 0, 1, 1, 1, 2},  {-1, 0, 0, 0, 1, 1}, {0, -1, 0, 1, 0, 1},
                           {0, 0, -1, 1, 1, 0}, {5, 5, 5, 6, 6, 6}};
    GuardBoxes table;
    const std::uint32_t first = table.add(boxes);
    const std::array<Vec3, 5> origins{Vec3{1, 1, 1}, Vec3{0, 0, 0}, Vec3{1, 0.5, 0.5},
                                      Vec3{-3, 1, 1}, Vec3{0.5, 0.5, 0.5}};
    const std::array<Vec3, 6> directions{Vec3{1, 1, 1},  Vec3{1, 0, 0},      Vec3{0, 1, -1},
                                         Vec3{-1, 2, 3}, Vec3{1, 1e-300, 0}, Vec3{3, 3, 3}};
    int met = 0;
    for (const Vec3& o : origins) {
        for (const Vec3& d : directions) {
            const LineProbe line(Ray{o, d});
            const std::uint32_t found = table.met(line, first, 0xffu);
            EXPECT_EQ(found, one_by_one(line, boxes, 0xffu))
                << "origin " << o.x << " " << o.y << " " << o.z << ", direction " << d.x << " "
                << d.y << " " << d.z;
            met += std::popcount(found);
        }
    }
    EXPECT_GT(met, 30);  // the lines do meet boxes: the test compares answers, not only misses
}

}  // namespace
}  // namespace rt::test
