// A single ray's cost to the BVH and to Embree on the lab's 100k soup, in two kinds of rays:
// rays that leave the scene's box behind them (each method sets the ray up, tests the root's
// children and stops), and rays that start inside the box and cross it in every direction (the
// walk, with most of its nodes and leaves out of the cache). The lab's random rays mix both kinds,
// so the two show which part of a method's random-ray rate is the walk and which the fixed cost.
// Counters, per ray: hits, wide nodes visited and exact tests (the BVH's; Embree counts none).
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"
#include "rt/accel/make_accelerator.h"
#include "rt/scene/scene.h"

#include <benchmark/benchmark.h>

#include "support/meshes/generated_meshes.h"

namespace rt::bench {
namespace {

constexpr int kRays = 4096;

const Scene& soup() {
    static const Scene scene = test::make_triangle_soup(100000);
    return scene;
}

// Origins on a sphere three box sizes from the middle, and directions pointing outwards: no ray
// meets the box (`leaving`); or origins inside the box and directions in every direction.
std::vector<Ray> rays(const Scene& scene, bool leaving) {
    const auto [lo, hi] = scene.bounds();
    const Vec3 middle = (lo + hi) * 0.5;
    const Vec3 extent = hi - lo;
    const double size = length(extent);
    std::mt19937_64 random(11);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> unit(-0.5, 0.5);
    std::vector<Ray> out;
    out.reserve(kRays);
    while (out.size() < kRays) {
        const Vec3 way{normal(random), normal(random), normal(random)};
        if (dot(way, way) < 1e-12) {
            continue;
        }
        const Vec3 out_of_middle = normalize(way);
        if (leaving) {
            out.push_back({middle + out_of_middle * (3.0 * size), out_of_middle});
        } else {
            const Vec3 inside = middle + Vec3{extent.x * unit(random), extent.y * unit(random),
                                              extent.z * unit(random)};
            out.push_back({inside, out_of_middle});
        }
    }
    return out;
}

void trace(benchmark::State& state, AccelKind kind, bool leaving) {
    AccelSettings settings;
    settings.kind = kind;
    settings.build_threads = 1;
    std::unique_ptr<Accelerator> accel;
    try {
        accel = make_accelerator(soup(), settings);
    } catch (const NotImplementedError&) {
        state.SkipWithError("this build has no such method");
        return;
    }
    const std::vector<Ray> traced = rays(soup(), leaving);
    TraceCounters counters;
    std::uint64_t hits = 0;
    for (auto _ : state) {
        for (const Ray& ray : traced) {
            hits += accel->closest_hit(ray, Interval{}, counters).has_value() ? 1 : 0;
        }
    }
    const auto rays_traced = static_cast<double>(state.iterations()) * kRays;
    state.SetItemsProcessed(state.iterations() * kRays);
    state.counters["hits"] = static_cast<double>(hits) / rays_traced;
    state.counters["nodes"] = static_cast<double>(counters.nodes_visited) / rays_traced;
    state.counters["tests"] = static_cast<double>(counters.polygon_tests) / rays_traced;
}

void leaving_rays_bvh(benchmark::State& state) {
    trace(state, AccelKind::Bvh, true);
}
void leaving_rays_embree(benchmark::State& state) {
    trace(state, AccelKind::Embree, true);
}
void crossing_rays_bvh(benchmark::State& state) {
    trace(state, AccelKind::Bvh, false);
}
void crossing_rays_embree(benchmark::State& state) {
    trace(state, AccelKind::Embree, false);
}

}  // namespace

BENCHMARK(leaving_rays_bvh);
BENCHMARK(leaving_rays_embree);
BENCHMARK(crossing_rays_bvh);
BENCHMARK(crossing_rays_embree);

}  // namespace rt::bench
