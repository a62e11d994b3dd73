// rt_scene_bench [--repeat N] [--csv FILE] SCENE [rt switches]: loads a scene, builds its
// accelerator and renders it N times through the library, printing wall times and rays/s.
#include <chrono>
#include <exception>
#include <iostream>

#include "rt/accel/accelerator_stack.h"
#include "rt/app/run.h"
#include "rt/app/run_settings.h"
#include "rt/app/switch_parser.h"
#include "rt/core/error.h"
#include "rt/render/film_window.h"
#include "rt/scene/read/load_scene.h"

#include "bench_arguments.h"
#include "bench_report.h"

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int bench(const std::vector<std::string>& args) {
    const rt::bench::BenchArguments arguments = rt::bench::split_bench_arguments(args);
    const rt::Options options = rt::parse_command_line(arguments.rt_args);
    if (options.show_help || options.show_usage) {
        std::cout << rt::bench::bench_usage();
        return 0;
    }
    rt::RunConsole console;
    console.warning = [](const std::string& m) {
        std::cerr << "rt_scene_bench: warning: " << m << '\n';
    };
    console.note = [](const std::string& m) { std::cerr << "rt_scene_bench: " << m << '\n'; };

    rt::bench::BenchRun run;
    run.scene = options.scene;
    auto start = std::chrono::steady_clock::now();
    rt::Diagnostics diagnostics;
    diagnostics.set_warning_sink(console.warning);
    rt::Scene scene =
        rt::load_scene(rt::resolve_scene_path(options.scene), options.dialect, diagnostics);
    run.load_seconds = seconds_since(start);

    rt::RenderSettings settings;
    settings.shading = rt::run_shading(options);
    rt::prepare_scene(scene, options, settings.shading);  // -E, -K
    settings.window = rt::film_window(scene.view.window, options.start_line);
    settings.threads = options.threads;
    start = std::chrono::steady_clock::now();
    const rt::AcceleratorStack stack(scene, options.accel,
                                     {console.note, console.warning, console.trace});
    const rt::Accelerator* accel = &stack.top();
    run.build_seconds = seconds_since(start);

    run.accelerator = std::string(accel->name());
    run.polygons = scene.polygons.size();
    run.width = settings.window.width();
    run.height = settings.window.height();
    run.renders = rt::bench::time_renders(scene, *accel, settings, arguments.repeat);
    std::cout << rt::bench::describe(run);
    if (arguments.csv) {
        rt::bench::append_csv_row(*arguments.csv, run);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return bench(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const rt::UsageError& e) {
        std::cerr << "rt_scene_bench: " << e.what() << '\n' << rt::bench::bench_usage();
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rt_scene_bench: " << e.what() << '\n';
        return 1;
    }
}
