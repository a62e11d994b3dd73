// rt_voxel_bench: build time, memory and single-thread rays per second of SEADS and the octree on
// cube spheres of 1k to 1M triangles (the yardstick). Usage (bench/README.md):
//   [ONLY=seads|octree] [SIDE=n] [DEPTH=n] build-bench/bin/rt_voxel_bench [max_triangles [rays
//   [min_triangles]]]
// (--only, --side and --depth are the same as the variables).
// Rays are eye rays through a square grid of pixels in raster order, as the renderer traces them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "rt/accel/make_accelerator.h"
#include "rt/accel/octree_depth_for.h"

#include "command_line/command_line.h"
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

struct VoxelBenchArguments {
    int max_triangles = 1000000;
    int ray_count = 200000;
    int min_triangles = 1000;
    std::string only;  ///< "seads" or "octree": measure just that one
    int side = 0;      ///< SEADS voxels a side; 0: the suggested size per sphere
    int depth = 0;     ///< octree depth; 0: the suggested depth per sphere
};

void add_options(CLI::App& app, VoxelBenchArguments& a) {
    const CLI::Validator count = rt::cli::whole_number_at_least(1);
    app.add_option("max_triangles", a.max_triangles, "the largest sphere (default 1000000)")
        ->type_name("")
        ->transform(count);
    app.add_option("rays", a.ray_count, "eye rays per measurement (default 200000)")
        ->type_name("")
        ->transform(count);
    app.add_option("min_triangles", a.min_triangles,
                   "the smallest sphere; each next one has ten times as many\n"
                   "triangles (default 1000)")
        ->type_name("")
        ->transform(count);
    app.add_option("--only", a.only, "measure just seads or octree")
        ->type_name("NAME")
        ->envname("ONLY")
        ->check(CLI::IsMember({"seads", "octree"}).description(""));
    app.add_option("--side", a.side, "SEADS voxels a side (default: the suggested size)")
        ->type_name("N")
        ->envname("SIDE")
        ->transform(count);
    app.add_option("--depth", a.depth, "octree depth (default: the suggested depth)")
        ->type_name("N")
        ->envname("DEPTH")
        ->transform(count);
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

// Both methods on each sphere from min_triangles up, ten times more triangles each time.
void run(const VoxelBenchArguments& a) {
    for (int triangles = a.min_triangles; triangles <= a.max_triangles; triangles *= 10) {
        const rt::Scene scene = rt::test::make_cube_sphere(static_cast<std::uint32_t>(triangles));
        rt::AccelSettings seads;
        seads.kind = rt::AccelKind::Seads;
        // The suggested size (accel_settings.h): finer grids walk more empty voxels than they
        // save tests.
        seads.seads_resolution = a.side > 0 ? a.side : rt::suggested_seads_resolution(triangles);
        if (a.only.empty() || a.only == "seads") {
            measure(scene, seads, a.ray_count);
        }
        rt::AccelSettings octree;
        octree.kind = rt::AccelKind::Octree;
        octree.octree.depth = a.depth > 0 ? a.depth : rt::octree_depth_for(scene);
        if (a.only.empty() || a.only == "octree") {
            measure(scene, octree, a.ray_count);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        CLI::App app(
            "Build time, memory and single-thread rays per second of SEADS and the octree\n"
            "on cube spheres of min_triangles to max_triangles triangles.",
            "rt_voxel_bench");
        rt::cli::configure(app);
        VoxelBenchArguments a;
        add_options(app, a);
        if (const std::optional<int> stop =
                rt::cli::parse(app, argc, argv, rt::cli::BareCommand::Runs)) {
            return *stop;
        }
        run(a);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "rt_voxel_bench: " << e.what() << '\n';
        return 1;
    }
}
