// The inline step to the next value (core/next_up.h) gives the library's std::nextafter bit for
// bit, in float and in double: on zeros of both signs, subnormals, the largest values,
// infinities, NaN, and random bit patterns of every exponent.
#include "rt/core/next_up.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

namespace rt {
namespace {

template <class T>
void expect_nextafter_both_ways() {
    using Limits = std::numeric_limits<T>;
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    std::vector<T> values = {T{0},
                             -T{0},
                             Limits::denorm_min(),
                             -Limits::denorm_min(),
                             Limits::min(),
                             -Limits::min(),
                             Limits::max(),
                             -Limits::max(),
                             Limits::infinity(),
                             -Limits::infinity(),
                             Limits::quiet_NaN(),
                             T{1},
                             T{-1},
                             T{0.1},
                             T{1e30}};
    std::mt19937_64 random(3);
    for (int i = 0; i < 100000; ++i) {
        values.push_back(std::bit_cast<T>(static_cast<Bits>(random())));
    }
    for (const T x : values) {
        const T up = std::nextafter(x, Limits::infinity());
        const T down = std::nextafter(x, -Limits::infinity());
        if (std::isnan(x)) {
            EXPECT_TRUE(std::isnan(next_up(x)) && std::isnan(next_down(x)));
            continue;
        }
        EXPECT_EQ(std::bit_cast<Bits>(next_up(x)), std::bit_cast<Bits>(up)) << x;
        EXPECT_EQ(std::bit_cast<Bits>(next_down(x)), std::bit_cast<Bits>(down)) << x;
    }
}

TEST(NextUp, IsNextafterInFloat) {
    expect_nextafter_both_ways<float>();
}

TEST(NextUp, IsNextafterInDouble) {
    expect_nextafter_both_ways<double>();
}

}  // namespace
}  // namespace rt
