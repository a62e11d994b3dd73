#include "rt/render/random_rays.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "rt/sampling/sample_stream.h"

namespace rt {

namespace {

constexpr std::uint64_t kBatch = 4096;

Ray random_ray(const Vec3& lo, const Vec3& size, std::uint64_t seed, std::uint64_t index) {
    SampleStream s(seed, static_cast<int>(index & 0xffffffffU), static_cast<int>(index >> 32),
                   0xffffffffU);
    const Vec3 origin{lo.x + size.x * s.uniform(), lo.y + size.y * s.uniform(),
                      lo.z + size.z * s.uniform()};
    const double z = 1.0 - 2.0 * s.uniform();
    const double phi = 2.0 * std::numbers::pi * s.uniform();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {origin, {r * std::cos(phi), r * std::sin(phi), z}};
}

}  // namespace

KindCounters fire_random_rays(const Scene& scene, const Accelerator& accel, std::uint64_t count,
                              std::uint64_t seed, int threads) {
    const Box3 bounds = scene.bounds();
    const Vec3 centre = bounds.centre();
    const Vec3 doubled_lo = centre - bounds.extent();
    const Vec3 size = bounds.extent() * 2.0;
    int n = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
    n = std::max(1, n);
    std::vector<KindCounters> counters(static_cast<std::size_t>(n));
    std::atomic<std::uint64_t> next{0};
    const auto work = [&](KindCounters& mine) {
        TraceCounters& c = mine[RayKind::Random];
        for (;;) {
            const std::uint64_t first = next.fetch_add(kBatch);
            if (first >= count) {
                return;
            }
            for (std::uint64_t i = first; i < std::min(count, first + kBatch); ++i) {
                ++c.rays;
                if (accel.closest_hit(random_ray(doubled_lo, size, seed, i), {0.0, kBeyondAnyScene},
                                      c)) {
                    ++c.hits;
                }
            }
        }
    };
    std::vector<std::thread> workers;
    for (int i = 1; i < n; ++i) {
        workers.emplace_back(work, std::ref(counters[static_cast<std::size_t>(i)]));
    }
    work(counters[0]);
    for (std::thread& t : workers) {
        t.join();
    }
    KindCounters total;
    for (const KindCounters& c : counters) {
        total += c;
    }
    return total;
}

}  // namespace rt
