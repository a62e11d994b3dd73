#include "rt/accel/exit_culling/eye_coverage.h"

#include <bit>

#include <fmt/format.h>

namespace rt {

EyeCoverage::EyeCoverage(const Camera& camera, const Box3& scene_bounds,
                         const OccupiedCells& cells) {
    EyeView eye(camera, scene_bounds);
    if (!eye.usable()) {
        inactive_reason_ = "the view has no area";
        return;
    }
    const std::size_t pixels = static_cast<std::size_t>(camera.width) * camera.height;
    if (pixels > kMaxPixels) {
        inactive_reason_ = fmt::format("the view has {} pixels, over {}", pixels, kMaxPixels);
        return;
    }
    eye_ = eye;
    width_ = camera.width;
    height_ = camera.height;
    bits_.assign((pixels + 63) / 64, 0);
    for (const OccupiedCells::Node& node : cells.tree()) {
        if (node.first_child >= 0) {
            continue;  // the leaves hold every box
        }
        const PixelFootprint f = eye_.footprint_of(node.box);
        for (int y = f.y0; y <= f.y1 && !f.empty(); ++y) {
            cover(y, f.x0, f.x1);
        }
    }
}

void EyeCoverage::cover(int y, int x0, int x1) {
    const std::size_t first = static_cast<std::size_t>(y) * width_ + x0;
    const std::size_t last = static_cast<std::size_t>(y) * width_ + x1;
    for (std::size_t word = first / 64; word <= last / 64; ++word) {
        const std::size_t lo = word == first / 64 ? first % 64 : 0;
        const std::size_t hi = word == last / 64 ? last % 64 : 63;
        // Bits lo..hi: all ones shifted, without a shift by 64.
        const std::uint64_t up_to_hi =
            hi == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (hi + 1)) - 1;
        bits_[word] |= up_to_hi & ~((std::uint64_t{1} << lo) - 1);
    }
}

std::size_t EyeCoverage::covered_pixels() const {
    std::size_t covered = 0;
    for (const std::uint64_t word : bits_) {
        covered += static_cast<std::size_t>(std::popcount(word));
    }
    return covered;
}

}  // namespace rt
