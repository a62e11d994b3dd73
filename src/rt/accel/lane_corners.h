// A packet's copy of its triangle lanes' corner indices into Scene::positions, for their exact
// tests (lane_exact_hit.h), in 32 bytes for four lanes: corner 0's index, and corners 1 and 2 as
// signed 16-bit steps from it. Twelve full indices took 48 bytes and made a packet 208 bytes,
// four cache lines; with these it is 192, three lines on a 64-byte boundary. A mesh's triangle
// has its corners near each other in the positions (a soup's are adjacent, a grid's a row apart),
// so the steps fit; a triangle whose steps do not fit is marked as not one, and its exact test
// reads its corners from the scene, as a polygon of more corners does: the same corners, so the
// same answer.
#pragma once

#include <cstdint>
#include <limits>

namespace rt {

/// In LaneCorners::first: the lane's polygon is not a triangle (or the lane is unused, or its
/// steps do not fit), and the exact test reads the Scene.
inline constexpr std::uint32_t kNotTriangle = 0xffffffffu;

struct LaneCorners {
    std::uint32_t first[4];   ///< [lane] corner 0's index into Scene::positions, or kNotTriangle
    std::int16_t step[2][4];  ///< [corner - 1][lane]: the corner's index minus corner 0's

    /// Sets `lane` to a triangle's corner indices (in its Scene::corners order), or to
    /// kNotTriangle for null or for corners too far apart for a step.
    void set(int lane, const std::uint32_t* triangle) {
        first[lane] = kNotTriangle;
        step[0][lane] = 0;
        step[1][lane] = 0;
        if (triangle == nullptr || triangle[0] == kNotTriangle) {
            return;
        }
        std::int16_t steps[2];
        for (int v = 1; v < 3; ++v) {
            const std::int64_t difference =
                static_cast<std::int64_t>(triangle[v]) - static_cast<std::int64_t>(triangle[0]);
            if (difference < std::numeric_limits<std::int16_t>::min() ||
                difference > std::numeric_limits<std::int16_t>::max()) {
                return;
            }
            steps[v - 1] = static_cast<std::int16_t>(difference);
        }
        first[lane] = triangle[0];
        step[0][lane] = steps[0];
        step[1][lane] = steps[1];
    }

    void copy_lane(int from, int to) {
        first[to] = first[from];
        step[0][to] = step[0][from];
        step[1][to] = step[1][from];
    }

    [[nodiscard]] bool is_triangle(int lane) const { return first[lane] != kNotTriangle; }

    /// Corner `v`'s index, for a triangle lane.
    [[nodiscard]] std::uint32_t corner(int v, int lane) const {
        // Unsigned arithmetic wraps, so a negative step comes out as the difference it was.
        return v == 0
                   ? first[lane]
                   : first[lane] +
                         static_cast<std::uint32_t>(static_cast<std::int32_t>(step[v - 1][lane]));
    }
};
static_assert(sizeof(LaneCorners) == 32);

}  // namespace rt
