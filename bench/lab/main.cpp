// rt_lab: builds every intersection method this rt has on the same meshes and traces the same
// rays through each, printing a table (and, on request, CSV and an SVG plot). bench/lab/README.md.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/load_scene.h"
#include "rt/scene/scene.h"

#include "command_line/command_line.h"
#include "lab_measure.h"
#include "lab_options.h"
#include "lab_rays.h"
#include "lab_report.h"
#include "lab_shares.h"
#include "support/meshes/generated_meshes.h"
#include "svg_plot.h"

namespace {

using rt::lab::LabOptions;

// Every method on one scene, --rounds times. Even rounds take the methods backward, so that no
// method always builds and runs right after the same one (docs/lab/bvh-build-order-2026-12-04.md).
void run_scene(const rt::Scene& scene, const std::string& mesh, const LabOptions& options,
               std::vector<rt::lab::Measurement>& results) {
    rt::lab::LabRays rays;
    rays.primary = rt::lab::camera_rays(scene);
    rays.random = rt::lab::random_rays(scene, rays.primary.size());
    for (unsigned round = 1; round <= options.rounds; ++round) {
        std::vector<rt::AccelKind> order = options.accels;
        if (round % 2 == 0) {
            std::reverse(order.begin(), order.end());
        }
        if (options.rounds > 1) {
            std::cout << "round " << round << " of " << options.rounds << '\n';
        }
        for (const rt::AccelKind kind : order) {
            if (kind == rt::AccelKind::BruteForce &&
                rt::lab::fan_triangles(scene) > options.brute_force_largest) {
                continue;
            }
            if (auto m = rt::lab::measure(scene, mesh, kind, rays, options)) {
                m->round = round;
                rt::lab::print_table_row(std::cout, *m);
                results.push_back(*m);
            }
        }
    }
}

int run(const LabOptions& options) {
    std::vector<rt::lab::Measurement> results;
    rt::lab::print_table_header(std::cout);
    for (const std::string& mesh : options.meshes) {
        if (mesh == "twocubes") {
            rt::Diagnostics diagnostics;
            const auto file = std::filesystem::path(options.source_dir) / "scenes" / "twocubes.scn";
            run_scene(rt::load_scene(file, rt::ReaderDialect{}, diagnostics), mesh, options,
                      results);
            continue;
        }
        for (const std::uint32_t size : options.sizes) {
            rt::Scene scene = mesh == "sphere" ? rt::test::make_tessellated_sphere(size)
                                               : rt::test::make_triangle_soup(size);
            rt::move_to_huge_pages(scene);  // as load_scene does
            run_scene(scene, mesh, options, results);
        }
    }
    if (options.pin_cpu != LabOptions::kNoPin && !results.empty()) {
        const bool all_there = std::all_of(results.begin(), results.end(), [&](const auto& m) {
            return m.pinned_cpu == options.pin_cpu;
        });
        std::cout << (all_there ? "one-thread runs on CPU " : "one-thread runs NOT all on CPU ")
                  << options.pin_cpu << " (--pin)\n";
    }
    rt::lab::print_shares(std::cout, rt::lab::shares_of_embree(results), options.rounds);
    if (!options.csv_file.empty()) {
        rt::lab::write_csv(options.csv_file, results);
    }
    // The plots draw one point a method and size: the median of the rounds.
    const std::vector<rt::lab::Measurement> medians = rt::lab::median_over_rounds(results);
    if (!options.svg_file.empty()) {
        rt::lab::write_svg_plot(options.svg_file, medians);
    }
    if (!options.time_svg_file.empty()) {
        rt::lab::write_time_plot(options.time_svg_file, medians);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app(
        "Every intersection method on the same meshes and rays: build time, memory and\n"
        "rays per second (bench/lab/README.md).",
        "rt_lab");
    rt::cli::configure(app);
    LabOptions options;
    rt::lab::add_lab_options(app, options);
    if (const std::optional<int> stop =
            rt::cli::parse(app, argc, argv, rt::cli::BareCommand::Runs)) {
        return *stop;
    }
    try {
        return run(options);
    } catch (const std::exception& e) {
        std::cerr << "rt_lab: " << e.what() << '\n';
        return 1;
    }
}
