// Brute force on the shipped twocubes scene: closest_hit() and occluded() for the eye rays of a
// coarse grid over its view, the rays a render starts with.
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/core/diagnostics.h"
#include "rt/geometry/camera.h"
#include "rt/scene/read/load_scene.h"

#include <benchmark/benchmark.h>

namespace rt::bench {
namespace {

constexpr Interval kAhead{0.0, kBeyondAnyScene};

Scene load_twocubes() {
    Diagnostics quiet;
    return load_scene(RT_SOURCE_DIR "/scenes/twocubes.scn", ReaderDialect{}, quiet);
}

// Eye rays through the centres of a columns x rows grid over the whole view area.
std::vector<Ray> eye_rays(const Scene& scene, int columns, int rows) {
    const Camera camera = scene.view.camera();
    std::vector<Ray> rays;
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            rays.push_back(camera.primary_ray((i + 0.5) * scene.view.width / columns,
                                              (j + 0.5) * scene.view.height / rows));
        }
    }
    return rays;
}

void brute_force_closest_hit_twocubes(benchmark::State& state) {
    const Scene scene = load_twocubes();
    const BruteForce accel(scene);
    const std::vector<Ray> rays = eye_rays(scene, 64, 50);
    TraceCounters counters;
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            const std::optional<Hit> hit = accel.closest_hit(ray, kAhead, counters);
            hits += hit.has_value() ? 1 : 0;
            benchmark::DoNotOptimize(hit);
        }
    }
    const auto rays_done = state.iterations() * static_cast<std::int64_t>(rays.size());
    state.SetItemsProcessed(rays_done);
    state.counters["polygons"] = static_cast<double>(scene.polygons.size());
    state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(rays_done);
}

void brute_force_occluded_twocubes(benchmark::State& state) {
    const Scene scene = load_twocubes();
    const BruteForce accel(scene);
    const std::vector<Ray> rays = eye_rays(scene, 64, 50);
    TraceCounters counters;
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            benchmark::DoNotOptimize(accel.occluded(ray, kAhead, counters));
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays.size()));
}

BENCHMARK(brute_force_closest_hit_twocubes);
BENCHMARK(brute_force_occluded_twocubes);

}  // namespace
}  // namespace rt::bench
