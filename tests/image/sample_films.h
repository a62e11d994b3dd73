// A small film whose values test the picture formats' round trips (.gro, .exr), and the check that
// two films are the same bit for bit.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "rt/image/film.h"

#include <gtest/gtest.h>

namespace rt::test {

/// A 6 x 5 view with a 4 x 3 window, rows from `first_finished_row` finished, and values whose bits
/// must survive exactly (-0, the smallest denormal, the largest float, 1/3).
inline Film sample_film(int first_finished_row) {
    Film film(6, 5, PixelRect{1, 1, 4, 3});
    for (std::size_t i = 0; i < film.data().size(); ++i) {
        film.data()[i] = static_cast<float>(i) * 0.37F - 2.0F;
    }
    film.data()[0] = -0.0F;
    film.data()[1] = std::numeric_limits<float>::denorm_min();
    film.data()[2] = std::numeric_limits<float>::max();
    film.data()[3] = 1.0F / 3.0F;
    film.set_first_finished_row(first_finished_row);
    film.mapping = {2.5, false};
    film.provenance = {"twocubes", "-Dd -m2.5 -c", "rt 0.1.0", "2024-05-06T07:08:09Z", "", "", ""};
    return film;
}

/// Every field and every pixel's bits equal.
inline void expect_same_film(const Film& a, const Film& b) {
    EXPECT_EQ(a.view_width(), b.view_width());
    EXPECT_EQ(a.view_height(), b.view_height());
    EXPECT_EQ(a.window(), b.window());
    EXPECT_EQ(a.first_finished_row(), b.first_finished_row());
    EXPECT_EQ(a.mapping.multiplier, b.mapping.multiplier);
    EXPECT_EQ(a.mapping.clip, b.mapping.clip);
    EXPECT_EQ(a.provenance.scene, b.provenance.scene);
    EXPECT_EQ(a.provenance.switches, b.provenance.switches);
    EXPECT_EQ(a.provenance.program, b.provenance.program);
    EXPECT_EQ(a.provenance.created, b.provenance.created);
    ASSERT_EQ(a.data().size(), b.data().size());
    for (std::size_t i = 0; i < a.data().size(); ++i) {
        EXPECT_EQ(std::bit_cast<std::uint32_t>(a.data()[i]),
                  std::bit_cast<std::uint32_t>(b.data()[i]))
            << "value " << i;
    }
}

}  // namespace rt::test
