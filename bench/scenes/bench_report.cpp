#include "bench_report.h"

#include <fstream>

#include "rt/core/error.h"

#include <fmt/format.h>

namespace rt::bench {

namespace {

double rays_per_second(const BenchRun& run) {
    const double seconds = run.renders.median();
    return seconds > 0.0 ? static_cast<double>(run.renders.counters.rays) / seconds : 0.0;
}

}  // namespace

std::string describe(const BenchRun& run) {
    const TraceCounters& c = run.renders.counters;
    std::string text = fmt::format(
        "scene        {}: {} polygons, {}x{} pixels\n"
        "accelerator  {} (built in {:.3f} s; scene loaded in {:.3f} s)\n"
        "threads      {}\n",
        run.scene, run.polygons, run.width, run.height, run.accelerator, run.build_seconds,
        run.load_seconds, run.renders.threads);
    text += fmt::format("renders      {}: median {:.4f} s, min {:.4f} s\n",
                        run.renders.seconds.size(), run.renders.median(), run.renders.minimum());
    text += fmt::format("per render   {} rays, {} polygon tests, {} hits\n", c.rays,
                        c.polygon_tests, c.hits);
    text +=
        fmt::format("throughput   {:.3f} Mrays/s (at the median)\n", rays_per_second(run) / 1e6);
    if (!run.replays.empty()) {
        // The rays the render asked the method about (the rays above less those answered
        // without it), per second of the whole render: the renderer's own work included.
        const double asked = static_cast<double>(run.recorded_rays);
        const double in_render = run.renders.median() > 0.0 ? asked / run.renders.median() : 0.0;
        text += fmt::format(
            "replay       {} rays asked of the method in one render: {:.3f} Mrays/s within it\n",
            run.recorded_rays, in_render / 1e6);
        for (const ReplayTimes& replay : run.replays) {
            const double median = median_of(replay.seconds);
            const double alone = median > 0.0 ? asked / median : 0.0;
            text += fmt::format(
                "  {:<10} {} replays on {} thread{}: median {:.4f} s, min {:.4f} s, {:.3f} "
                "Mrays/s; the render keeps {:.0f} % of it ({} hits and blocked)\n",
                replay.accelerator, replay.seconds.size(), replay.threads,
                replay.threads == 1 ? "" : "s", median, minimum_of(replay.seconds), alone / 1e6,
                alone > 0.0 ? 100.0 * in_render / alone : 0.0, replay.found);
        }
    }
    return text;
}

void append_csv_row(const std::filesystem::path& file, const BenchRun& run) {
    const bool fresh = !std::filesystem::exists(file) || std::filesystem::file_size(file) == 0;
    std::ofstream out(file, std::ios::app);
    if (fresh) {
        out << "scene,accelerator,polygons,threads,width,height,renders,median_s,min_s,rays,"
               "polygon_tests,rays_per_s\n";
    }
    out << fmt::format("{},{},{},{},{},{},{},{:.6f},{:.6f},{},{},{:.0f}\n", run.scene,
                       run.accelerator, run.polygons, run.renders.threads, run.width, run.height,
                       run.renders.seconds.size(), run.renders.median(), run.renders.minimum(),
                       run.renders.counters.rays, run.renders.counters.polygon_tests,
                       rays_per_second(run));
    if (!out) {
        throw IoError("cannot write " + file.string());
    }
}

}  // namespace rt::bench
