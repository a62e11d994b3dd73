// The per-ray set-up every accelerator pays before its first test: the float pre-filters'
// FloatRay and the exact test's RaySpace, on rays in every direction.
#include <random>
#include <vector>

#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/geometry/ray_polygon.h"

#include <benchmark/benchmark.h>

namespace rt::bench {
namespace {

constexpr int kRays = 4096;

std::vector<Ray> rays_in_every_direction() {
    std::mt19937_64 random(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> place(-10.0, 10.0);
    std::vector<Ray> rays;
    rays.reserve(kRays);
    for (int i = 0; i < kRays; ++i) {
        rays.push_back({{place(random), place(random), place(random)},
                        {normal(random), normal(random), normal(random)}});
    }
    return rays;
}

void float_ray_setup(benchmark::State& state) {
    const std::vector<Ray> rays = rays_in_every_direction();
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            const FloatRay prepared(ray, 12.0);
            benchmark::DoNotOptimize(prepared);
        }
    }
    state.SetItemsProcessed(state.iterations() * kRays);
}

void ray_space_setup(benchmark::State& state) {
    const std::vector<Ray> rays = rays_in_every_direction();
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            const RaySpace prepared(ray);
            benchmark::DoNotOptimize(prepared);
        }
    }
    state.SetItemsProcessed(state.iterations() * kRays);
}

}  // namespace

BENCHMARK(float_ray_setup);
BENCHMARK(ray_space_setup);

}  // namespace rt::bench
