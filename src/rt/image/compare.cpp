#include "rt/image/compare.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "rt/core/error.h"

namespace rt {

namespace {

std::string size_of(const Image8& image) {
    return std::to_string(image.width) + " x " + std::to_string(image.height);
}

// The side of the largest all-true square in a row-major mask: each cell holds the side of the
// largest square whose bottom-right corner it is (the classic dynamic programme), one row kept.
int largest_true_square(const std::vector<bool>& mask, int width, int height) {
    std::vector<int> above(static_cast<std::size_t>(width) + 1, 0);
    std::vector<int> row(static_cast<std::size_t>(width) + 1, 0);
    int largest = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const auto cell = static_cast<std::size_t>(x) + 1;
            const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                   static_cast<std::size_t>(x);
            row[cell] = mask[at] ? 1 + std::min({row[cell - 1], above[cell], above[cell - 1]}) : 0;
            largest = std::max(largest, row[cell]);
        }
        std::swap(above, row);
    }
    return largest;
}

}  // namespace

ImageDifference compare_images(const Image8& a, const Image8& b, int threshold) {
    if (a.width != b.width || a.height != b.height || a.rgb.size() != a.pixel_count() * 3 ||
        b.rgb.size() != b.pixel_count() * 3) {
        throw Error("cannot compare a " + size_of(a) + " image with a " + size_of(b) + " image");
    }
    ImageDifference d;
    if (a.rgb.empty()) {
        return d;
    }
    double total = 0.0;
    std::size_t pixels_over = 0;
    std::vector<bool> wrong(a.pixel_count(), false);
    for (std::size_t p = 0; p < a.pixel_count(); ++p) {
        int pixel_max = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int diff = std::abs(int{a.rgb[p * 3 + c]} - int{b.rgb[p * 3 + c]});
            pixel_max = std::max(pixel_max, diff);
            total += diff;
        }
        d.max_channel_difference = std::max(d.max_channel_difference, pixel_max);
        wrong[p] = pixel_max > threshold;
        pixels_over += wrong[p] ? 1 : 0;
    }
    d.mean_absolute_difference = total / static_cast<double>(a.rgb.size());
    d.fraction_over_threshold =
        static_cast<double>(pixels_over) / static_cast<double>(a.pixel_count());
    d.largest_wrong_square = largest_true_square(wrong, a.width, a.height);
    return d;
}

}  // namespace rt
