// rt_adaptive_study [study options] SCENE [rt switches]: adaptive against uniform supersampling
// on one scene, measured against a far better-sampled reference (README.md).
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "rt/app/switch_parser.h"
#include "rt/core/error.h"
#include "rt/image/film_reference.h"

#include "command_line/command_line.h"
#include "study_arguments.h"
#include "study_report.h"
#include "study_scene.h"

namespace {

constexpr std::uint64_t kFirstReferenceSeed = 1001;

int study(rt::bench::StudyArguments arguments, const std::string& help) {
    const rt::Options options = rt::parse_command_line(arguments.rt_args);
    if (options.show_help || options.show_usage) {
        std::cout << help;
        return 0;
    }
    if (arguments.uniform.empty()) {
        for (const auto& [nx, ny] :
             {std::pair{2, 2}, {3, 2}, {3, 3}, {4, 3}, {4, 4}, {5, 4}, {5, 5}, {6, 5}, {6, 6}}) {
            arguments.uniform.push_back({nx, ny, false});
        }
    }
    if (arguments.adaptive.empty()) {
        for (const double var : {0.8, 0.4, 0.2, 0.1, 0.05, 0.025}) {
            arguments.adaptive.push_back({4, 4, true, var, var});
        }
    }
    rt::bench::StudyScene scene(options, arguments.window);
    const rt::PixelRect& w = scene.window();
    const double pixels = static_cast<double>(w.width()) * w.height();

    rt::FilmReference reference;
    for (int i = 0; i < arguments.reference_renders; ++i) {
        reference.add(scene.render(arguments.reference, kFirstReferenceSeed + i).film);
        std::cerr << "reference render " << i + 1 << " of " << arguments.reference_renders
                  << " done\n";
    }
    std::cout << "Scene " << options.scene << ", window " << w.left << ' ' << w.top << ' '
              << w.right << ' ' << w.bottom << " (" << w.width() << " x " << w.height()
              << "). Reference: the mean of " << arguments.reference_renders << " renders "
              << rt::bench::describe(arguments.reference) << ", seeds " << kFirstReferenceSeed
              << "..; its own noise RMS " << std::sqrt(reference.noise_variance())
              << " display levels (taken out of every error below).\n\n";

    std::vector<rt::bench::Measured> runs;
    std::vector<rt::bench::SamplingPlan> plans = arguments.uniform;
    plans.insert(plans.end(), arguments.adaptive.begin(), arguments.adaptive.end());
    for (const rt::bench::SamplingPlan& plan : plans) {
        for (int seed = 1; seed <= arguments.seeds; ++seed) {
            const rt::bench::StudyRender r = scene.render(plan, static_cast<std::uint64_t>(seed));
            runs.push_back(
                {plan, static_cast<std::uint64_t>(seed), r.spent, reference.rms_error(r.film)});
        }
        std::cerr << rt::bench::describe(plan) << " done\n";
    }
    rt::bench::print_plans(std::cout, runs, pixels);
    rt::bench::print_comparisons(std::cout, runs);
    if (arguments.csv) {
        std::ofstream csv(*arguments.csv);
        rt::bench::write_csv(csv, runs, pixels);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app(
        "Renders SCENE's window through the library with every plan and seeds 1..N: -Dx at each\n"
        "--uniform sample resolution, adaptive at each --adaptive resolution with -Xp and -Xr\n"
        "var (prob 0.2). Each picture's RMS error (display levels) is measured against the mean\n"
        "of M -Dx renders at the --reference resolution (seeds 1001..), less that mean's own\n"
        "noise. Prints each plan's rays and error, adaptive's error against uniform's at equal\n"
        "rays, and the rays each needs for the same error.",
        "rt_adaptive_study");
    rt::cli::configure(app, "[study options] SCENE [rt switches]");
    rt::bench::StudyArguments arguments;
    rt::bench::add_study_options(app, arguments);
    if (const std::optional<int> stop =
            rt::cli::parse(app, argc, argv, rt::cli::BareCommand::PrintsHelp)) {
        return *stop;
    }
    arguments.rt_args = app.remaining();
    try {
        return study(arguments, app.help());
    } catch (const rt::UsageError& e) {
        std::cerr << "rt_adaptive_study: " << e.what() << '\n'
                  << "rt_adaptive_study: run 'rt_adaptive_study --help' for the options\n";
        return rt::cli::kUsageExit;
    } catch (const std::exception& e) {
        std::cerr << "rt_adaptive_study: " << e.what() << '\n';
        return 1;
    }
}
