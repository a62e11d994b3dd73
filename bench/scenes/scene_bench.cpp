// rt_scene_bench [--repeat N] [--csv FILE] SCENE [rt switches]: loads a scene, builds its
// accelerator and renders it N times through the library, printing wall times and rays/s.
#include <chrono>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator_stack.h"
#include "rt/app/run.h"
#include "rt/app/run_settings.h"
#include "rt/app/switch_parser.h"
#include "rt/core/error.h"
#include "rt/render/film_window.h"
#include "rt/scene/read/load_scene.h"

#include "bench_arguments.h"
#include "bench_report.h"
#include "command_line/command_line.h"
#include "replay_timing.h"

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --replay: one render's queries, recorded, then asked again of the rendered stack and of the
// stacks of --replay-accels (rt's switches, with the method replaced), on the renders' threads.
void replay(const rt::bench::BenchArguments& arguments, const rt::Options& options,
            const rt::Scene& scene, const rt::RenderSettings& settings,
            const rt::Accelerator& rendered, const rt::RunConsole& console,
            rt::bench::BenchRun& run) {
    const rt::RecordedQueries recorded = rt::bench::record_render(scene, rendered, settings);
    run.recorded_rays = recorded.rays_asked;
    const int threads = run.renders.threads;
    run.replays.push_back(rt::bench::time_replays(recorded, rendered, threads, arguments.repeat));
    for (const std::string& name : arguments.replay_accels) {
        rt::AcceleratorStackSettings stack_settings = rt::run_accelerator_stack(options);
        stack_settings.method.kind = rt::accel_kind_from_name(name);  // checked by the parser
        const rt::AcceleratorStack stack(scene, stack_settings,
                                         {console.note, console.warning, console.trace});
        run.replays.push_back(
            rt::bench::time_replays(recorded, stack.top(), threads, arguments.repeat));
    }
}

int bench(const rt::bench::BenchArguments& arguments, const std::string& help) {
    const rt::Options options = rt::parse_command_line(arguments.rt_args);
    if (options.show_help || options.show_usage) {
        std::cout << help;
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
    const rt::AcceleratorStack stack(scene, rt::run_accelerator_stack(options),
                                     {console.note, console.warning, console.trace});
    const rt::Accelerator* accel = &stack.top();
    run.build_seconds = seconds_since(start);

    run.accelerator = std::string(accel->name());
    run.polygons = scene.polygons.size();
    run.width = settings.window.width();
    run.height = settings.window.height();
    run.renders = rt::bench::time_renders(scene, *accel, settings, arguments.repeat);
    if (arguments.replay || !arguments.replay_accels.empty()) {
        replay(arguments, options, scene, settings, *accel, console, run);
    }
    std::cout << rt::bench::describe(run);
    if (arguments.csv) {
        rt::bench::append_csv_row(*arguments.csv, run);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app(
        "Loads SCENE once, builds its accelerator once and renders it N times through the\n"
        "library, writing no picture; prints the median and minimum wall time per render and\n"
        "rays per second. rt's own switches apply: --threads N, --accel NAME, -Ds, -L and the\n"
        "rest (see rt --help).",
        "rt_scene_bench");
    rt::cli::configure(app, "[--repeat N] [--csv FILE] SCENE [rt switches]");
    rt::bench::BenchArguments arguments;
    rt::bench::add_bench_options(app, arguments);
    if (const std::optional<int> stop =
            rt::cli::parse(app, argc, argv, rt::cli::BareCommand::PrintsHelp)) {
        return *stop;
    }
    arguments.rt_args = app.remaining();
    try {
        return bench(arguments, app.help());
    } catch (const rt::UsageError& e) {
        std::cerr << "rt_scene_bench: " << e.what() << '\n'
                  << "rt_scene_bench: run 'rt_scene_bench --help' for the options\n";
        return rt::cli::kUsageExit;
    } catch (const std::exception& e) {
        std::cerr << "rt_scene_bench: " << e.what() << '\n';
        return 1;
    }
}
