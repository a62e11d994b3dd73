#include "rt/image/compare.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "rt/core/error.h"

namespace rt {

namespace {

std::string size_of(const Image8& image) {
    return std::to_string(image.width) + " x " + std::to_string(image.height);
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
    for (std::size_t p = 0; p < a.pixel_count(); ++p) {
        int pixel_max = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int diff = std::abs(int{a.rgb[p * 3 + c]} - int{b.rgb[p * 3 + c]});
            pixel_max = std::max(pixel_max, diff);
            total += diff;
        }
        d.max_channel_difference = std::max(d.max_channel_difference, pixel_max);
        pixels_over += pixel_max > threshold ? 1 : 0;
    }
    d.mean_absolute_difference = total / static_cast<double>(a.rgb.size());
    d.fraction_over_threshold =
        static_cast<double>(pixels_over) / static_cast<double>(a.pixel_count());
    return d;
}

}  // namespace rt
