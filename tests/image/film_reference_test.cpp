// A reference made of several renders, and errors against it with its own noise taken out.
#include "rt/image/film_reference.h"

#include <cmath>
#include <random>

#include "rt/core/error.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr double kLevel = 1.0 / 255.0;  // one display level, as an intensity

Film flat_film(int width, int height, double levels) {
    Film film(width, height, {0, 0, width - 1, height - 1});
    for (float& v : film.data()) {
        v = static_cast<float>(levels * kLevel);
    }
    return film;
}

TEST(FilmReference, TakesItsOwnNoiseOutOfTheError) {
    FilmReference reference;
    reference.add(flat_film(1, 1, 10.0));
    reference.add(flat_film(1, 1, 14.0));
    // Sample variance 8, so the mean of two varies by 4 levels squared.
    EXPECT_NEAR(reference.noise_variance(), 4.0, 1e-3);
    EXPECT_NEAR(reference.mean().pixel(0, 0).g / kLevel, 12.0, 1e-3);
    // A film at 15 is 3 levels from the mean: 9 - 4.
    EXPECT_NEAR(reference.mean_squared_error(flat_film(1, 1, 15.0)), 5.0, 1e-3);
    EXPECT_NEAR(reference.rms_error(flat_film(1, 1, 15.0)), std::sqrt(5.0), 1e-3);
    EXPECT_EQ(reference.rms_error(flat_film(1, 1, 12.0)), 0.0);  // negative estimates are 0
}

// Renders simulated as a truth plus independent noise: the corrected error estimates the
// film's own noise, where the raw difference would add the reference's.
TEST(FilmReference, EstimatesTheErrorAgainstTheTruth) {
    constexpr int kSide = 100;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> truth_levels(0.0, 200.0);
    Film truth = flat_film(kSide, kSide, 0.0);
    for (float& v : truth.data()) {
        v = static_cast<float>(truth_levels(random) * kLevel);
    }
    const auto noisy = [&](double sigma_levels) {
        std::normal_distribution<double> noise(0.0, sigma_levels * kLevel);
        Film film = truth;
        for (float& v : film.data()) {
            v = static_cast<float>(v + noise(random));
        }
        return film;
    };
    FilmReference reference;
    for (int i = 0; i < 4; ++i) {
        reference.add(noisy(2.0));  // the mean of four: variance 1
    }
    EXPECT_NEAR(reference.noise_variance(), 1.0, 0.05);
    EXPECT_NEAR(reference.mean_squared_error(noisy(1.5)), 2.25, 0.1);
    EXPECT_NEAR(reference.mean_squared_error(truth), 0.0, 0.05);
}

TEST(FilmReference, RefusesAnotherWindowAndNeedsTwoRenders) {
    FilmReference reference;
    reference.add(flat_film(2, 1, 1.0));
    EXPECT_THROW(reference.noise_variance(), Error);
    EXPECT_THROW(reference.add(flat_film(1, 2, 1.0)), Error);
}

}  // namespace
}  // namespace rt
