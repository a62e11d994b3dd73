// Ray-polygon test throughput on triangles, quads and 20-gons: with the ray prepared once (the
// form accelerators call in their loops) and prepared for every test.
#include <vector>

#include "rt/geometry/ray_polygon.h"

#include <benchmark/benchmark.h>

#include "one_polygon_scene.h"

namespace rt::bench {
namespace {

constexpr int kRays = 4096;
constexpr Interval kAhead{0.0, kBeyondAnyScene};

void intersect_polygon_prepared_ray(benchmark::State& state) {
    const Scene scene = regular_polygon_scene(static_cast<int>(state.range(0)));
    std::vector<RaySpace> spaces;
    for (const Ray& ray : rays_around_unit_polygon(kRays)) {
        spaces.emplace_back(ray);
    }
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (const RaySpace& space : spaces) {
            const std::optional<double> t = intersect_polygon(space, scene.polygon_view(0), kAhead);
            hits += t.has_value() ? 1 : 0;
            benchmark::DoNotOptimize(t);
        }
    }
    state.SetItemsProcessed(state.iterations() * kRays);
    state.counters["hit_fraction"] =
        static_cast<double>(hits) / static_cast<double>(state.iterations() * kRays);
}

void intersect_polygon_fresh_ray(benchmark::State& state) {
    const Scene scene = regular_polygon_scene(static_cast<int>(state.range(0)));
    const std::vector<Ray> rays = rays_around_unit_polygon(kRays);
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            benchmark::DoNotOptimize(intersect_polygon(ray, scene.polygon_view(0), kAhead));
        }
    }
    state.SetItemsProcessed(state.iterations() * kRays);
}

// The exact fallback's cost: collinear inputs never pass the quick filter.
void edge_sign_quick_or_exact(benchmark::State& state) {
    const bool degenerate = state.range(0) != 0;
    std::vector<double> values;
    for (int i = 1; i <= 1024; ++i) {
        values.push_back(0.1 * i);
    }
    for (auto _ : state) {
        for (std::size_t i = 0; i + 1 < values.size(); ++i) {
            const double x = values[i];
            const double y = degenerate ? values[i] * 3.0 : values[i + 1];
            benchmark::DoNotOptimize(edge_sign(x, y, values[i + 1], values[i + 1] * 3.0));
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values.size() - 1));
    state.SetLabel(degenerate ? "collinear (exact path)" : "general (quick path)");
}

BENCHMARK(intersect_polygon_prepared_ray)->ArgName("corners")->Arg(3)->Arg(4)->Arg(20);
BENCHMARK(intersect_polygon_fresh_ray)->ArgName("corners")->Arg(3)->Arg(4)->Arg(20);
BENCHMARK(edge_sign_quick_or_exact)->ArgName("collinear")->Arg(0)->Arg(1);

}  // namespace
}  // namespace rt::bench
