// The BVH's build on one thread, the lab's meshes at 100k triangles: the builder's own work, with
// neither the second core's share nor a fresh process's page faults (`rt_lab` times those), so
// that a change to the builder shows against a few percent of noise. Repeated builds reuse the
// memory the last one freed.
#include <cstdint>

#include "rt/accel/bvh/bvh.h"
#include "rt/scene/scene.h"

#include <benchmark/benchmark.h>

#include "support/meshes/generated_meshes.h"

namespace rt::bench {
namespace {

constexpr std::uint32_t kTriangles = 100000;

void build_one_thread(benchmark::State& state, const Scene& scene) {
    for (auto _ : state) {
        const Bvh bvh(scene, BvhSettings{1});
        benchmark::DoNotOptimize(bvh.memory_bytes());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kTriangles));
}

void bvh_build_sphere(benchmark::State& state) {
    static const Scene scene = test::make_tessellated_sphere(kTriangles);
    build_one_thread(state, scene);
}

void bvh_build_soup(benchmark::State& state) {
    static const Scene scene = test::make_triangle_soup(kTriangles);
    build_one_thread(state, scene);
}

}  // namespace

BENCHMARK(bvh_build_sphere)->Unit(benchmark::kMillisecond);
BENCHMARK(bvh_build_soup)->Unit(benchmark::kMillisecond);

}  // namespace rt::bench
