// A reference picture estimated as the mean of several independent renders, and how far another
// render is from the truth they estimate: the measure sampling studies judge renderers by.
#pragma once

#include <cstddef>
#include <vector>

#include "rt/image/film.h"

namespace rt {

class FilmReference {
public:
    /// Adds one render; every film must have the same window, and be independent of the others
    /// (another seed). Throws rt::Error for a film of another window.
    void add(const Film& film);

    int count() const { return count_; }

    /// The variance of the reference's own mean, averaged over every channel of every pixel, in
    /// display levels squared (an intensity of 1 is 255). Needs two films or more.
    double noise_variance() const;

    /// The mean squared difference between the film and the reference, less the reference's
    /// noise variance: an unbiased estimate of the film's squared error against the expected
    /// picture, if the film is independent of the reference's renders. Display levels squared.
    double mean_squared_error(const Film& film) const;

    /// The square root of mean_squared_error, 0 where the estimate comes out negative.
    double rms_error(const Film& film) const;

    /// The reference's mean picture.
    Film mean() const;

private:
    Film shape_;                  ///< the first film: its window and view size
    std::vector<double> mean_;    ///< per channel, intensities
    std::vector<double> square_;  ///< per channel, sums of squared deviations (Welford)
    int count_ = 0;
};

}  // namespace rt
