// rt_voxel_bench: build time, memory and single-thread rays per second of SEADS and the octree on
// cube spheres of 1k to 1M triangles (the yardstick). Usage (bench/README.md):
//   [ONLY=seads|octree] [SIDE=n] [DEPTH=n] build-bench/bin/rt_voxel_bench [max_triangles [rays
//   [min_triangles]]]
// Rays are eye rays through a square grid of pixels in raster order, as the renderer traces them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "rt/accel/make_accelerator.h"

#include "support/meshes/generated_meshes.h"

namespace {

// CPU time of this thread, not wall time: the machines we measure on are shared, and a thread
// waiting for a core should not count against the method.
double cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// CPU time of every thread of the process: the octree build fills subtrees on worker threads,
// and their time is the build's too.
double process_cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// SIDE=n and DEPTH=n in the environment override the grid size and octree depth.
int from_environment(const char* name, int fallback) {
    const char* value = std::getenv(name);
    return value != nullptr ? std::atoi(value) : fallback;
}

void measure(const rt::Scene& scene, const rt::AccelSettings& settings, int ray_count) {
    const double build_start = process_cpu_seconds();
    const auto accel = rt::make_accelerator(scene, settings);
    const double build = process_cpu_seconds() - build_start;
    // Eye rays in raster order, as the renderer traces them: a square grid of pixels whose
    // rays sweep a square a little larger than the sphere.
    const int side = std::max(1, static_cast<int>(std::sqrt(ray_count)));
    std::vector<rt::Ray> rays;
    rays.reserve(static_cast<std::size_t>(side) * side);
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            rt::Ray ray;
            ray.origin = {0.3, 0.2, 4.0};
            const rt::Vec3 target{-1.2 + 2.4 * (column + 0.5) / side,
                                  -1.2 + 2.4 * (row + 0.5) / side, 0.0};
            ray.direction = target - ray.origin;
            rays.push_back(ray);
        }
    }
    ray_count = static_cast<int>(rays.size());
    rt::TraceCounters counters;
    std::size_t hits = 0;
    const double trace_start = cpu_seconds();
    for (const rt::Ray& ray : rays) {
        hits += accel->closest_hit(ray, {}, counters) ? 1 : 0;
    }
    const double trace = cpu_seconds() - trace_start;
    const auto n = static_cast<double>(scene.polygons.size());
    std::printf(
        "%-7s %8zu tris  param %3d  build %7.1f ms  %6.1f B/tri  %5.2f Mrays/s  "
        "%5.1f tests/ray  %5.1f voxels/ray  hits %zu\n",
        std::string(accel->name()).c_str(), scene.polygons.size(),
        settings.kind == rt::AccelKind::Seads ? *settings.seads_resolution : *settings.octree.depth,
        build * 1e3, accel->memory_bytes() / n, ray_count / trace / 1e6,
        static_cast<double>(counters.polygon_tests) / ray_count,
        static_cast<double>(counters.voxels_stepped) / ray_count, hits);
}

}  // namespace

int main(int argc, char** argv) {
    const int max_triangles = argc > 1 ? std::atoi(argv[1]) : 1000000;
    const int ray_count = argc > 2 ? std::atoi(argv[2]) : 200000;
    const char* only = std::getenv("ONLY");  // "seads" or "octree": measure just that one
    const int min_triangles = argc > 3 ? std::atoi(argv[3]) : 1000;
    for (int triangles = min_triangles; triangles <= max_triangles; triangles *= 10) {
        const rt::Scene scene = rt::test::make_cube_sphere(static_cast<std::uint32_t>(triangles));
        rt::AccelSettings seads;
        seads.kind = rt::AccelKind::Seads;
        // About one voxel a side per cube root of the triangle count (measured best for the
        // sphere: finer grids walk more empty voxels than they save tests).
        seads.seads_resolution =
            from_environment("SIDE", rt::suggested_seads_resolution(triangles));
        if (only == nullptr || std::string(only) == "seads") {
            measure(scene, seads, ray_count);
        }
        rt::AccelSettings octree;
        octree.kind = rt::AccelKind::Octree;
        octree.octree.depth = from_environment("DEPTH", rt::suggested_octree_depth(triangles));
        if (only == nullptr || std::string(only) == "octree") {
            measure(scene, octree, ray_count);
        }
    }
    return 0;
}
