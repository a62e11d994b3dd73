#include "lab_rays.h"

#include <cmath>
#include <random>

namespace rt::lab {

std::vector<Ray> camera_rays(const Scene& scene) {
    const auto [lo, hi] = scene.bounds();
    const Vec3 middle = (lo + hi) * 0.5;
    const double radius = std::max(0.5 * length(hi - lo), 1e-9);
    // From a little above and to the side, so that axis-aligned scenes are not seen face-on.
    const Vec3 back = normalize(Vec3{0.3, 0.4, -1.0});
    const Vec3 eye = middle + back * (2.5 * radius);
    const Vec3 forward = -back;
    const Vec3 right = normalize(cross(Vec3{0, 1, 0}, forward));
    const Vec3 up = cross(forward, right);
    // The box's bounding sphere fills the height: half-angle asin(1 / 2.5).
    const double half_height = std::tan(std::asin(1.0 / 2.5));
    const double half_width = half_height * kImageWidth / kImageHeight;
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(kImageWidth) * kImageHeight);
    for (int y = 0; y < kImageHeight; ++y) {
        for (int x = 0; x < kImageWidth; ++x) {
            const double u = (2.0 * (x + 0.5) / kImageWidth - 1.0) * half_width;
            const double v = (1.0 - 2.0 * (y + 0.5) / kImageHeight) * half_height;
            rays.push_back({eye, forward + right * u + up * v});
        }
    }
    return rays;
}

std::vector<RayPacket> packets_of(const std::vector<Ray>& rays, int width) {
    std::vector<std::size_t> order;
    order.reserve(rays.size());
    if (width > 0) {
        const std::size_t w = static_cast<std::size_t>(width);
        const std::size_t rows = rays.size() / w;
        for (std::size_t row = 0; row < rows; row += 2) {
            for (std::size_t x = 0; x < w; x += 4) {
                for (std::size_t dy = 0; dy < 2; ++dy) {
                    for (std::size_t dx = 0; dx < 4; ++dx) {
                        const std::size_t i = (row + dy) * w + x + dx;
                        if (x + dx < w && row + dy < rows) {
                            order.push_back(i);
                        }
                    }
                }
            }
        }
    } else {
        for (std::size_t i = 0; i < rays.size(); ++i) {
            order.push_back(i);
        }
    }
    std::vector<RayPacket> packets;
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (i % kPacketSize == 0) {
            packets.emplace_back();
        }
        const int lane = static_cast<int>(i % kPacketSize);
        packets.back().rays[lane] = rays[order[i]];
        packets.back().active |= 1u << lane;
    }
    return packets;
}

std::vector<Ray> random_rays(const Scene& scene, std::size_t count, std::uint64_t seed) {
    const auto [lo, hi] = scene.bounds();
    const Vec3 middle = (lo + hi) * 0.5;
    const Vec3 size = hi - lo;
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<Ray> rays;
    rays.reserve(count);
    while (rays.size() < count) {
        const Vec3 origin =
            middle + Vec3{size.x * unit(random), size.y * unit(random), size.z * unit(random)};
        const Vec3 direction{normal(random), normal(random), normal(random)};
        if (dot(direction, direction) > 1e-12) {
            rays.push_back({origin, normalize(direction)});
        }
    }
    return rays;
}

}  // namespace rt::lab
