// How far apart two 8-bit pictures are: the measure golden-image tests judge renders by.
#pragma once

#include "rt/image/image8.h"

namespace rt {

struct ImageDifference {
    int max_channel_difference = 0;       ///< largest |a - b| over every channel of every pixel
    double mean_absolute_difference = 0;  ///< mean |a - b| over every channel of every pixel
    double fraction_over_threshold = 0;   ///< pixels with some channel differing by > threshold
    /// The side of the largest square of pixels that all differ by > threshold: scattered
    /// rounding differences give 1 at most, a hole or a blot in the picture more.
    int largest_wrong_square = 0;
};

/// Compares a and b pixel by pixel. Throws rt::Error unless they have the same size.
ImageDifference compare_images(const Image8& a, const Image8& b, int threshold);

}  // namespace rt
