#include "rt/scene/texture_image.h"

#include <algorithm>
#include <cmath>

namespace rt {

Rgb sample_bilinear(const TextureImage& image, double x, double y) {
    // Continuous coordinates of pixel centres: pixel i's centre is at i + 0.5.
    const double cx = std::clamp(x - 0.5, 0.0, static_cast<double>(image.width - 1));
    const double cy = std::clamp(y - 0.5, 0.0, static_cast<double>(image.height - 1));
    const int x0 = static_cast<int>(cx);
    const int y0 = static_cast<int>(cy);
    const int x1 = std::min(x0 + 1, image.width - 1);
    const int y1 = std::min(y0 + 1, image.height - 1);
    const double fx = cx - x0;
    const double fy = cy - y0;
    const auto texel = [&](int i, int j) {
        const std::size_t at =
            3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(image.width) +
                 static_cast<std::size_t>(i));
        return Rgb{image.rgb[at] / 255.0, image.rgb[at + 1] / 255.0, image.rgb[at + 2] / 255.0};
    };
    return texel(x0, y0) * ((1 - fx) * (1 - fy)) + texel(x1, y0) * (fx * (1 - fy)) +
           texel(x0, y1) * ((1 - fx) * fy) + texel(x1, y1) * (fx * fy);
}

}  // namespace rt
