#include "lab_options.h"

#include <charconv>
#include <limits>

#include "rt/core/text.h"

#include "command_line/command_line.h"
#include <sched.h>

namespace rt::lab {

namespace {

// A count like 1000, 10k or 1M, above 0, rewritten as plain decimal for CLI11 to convert.
CLI::Validator count() {
    return {[](std::string& word) -> std::string {
                std::string digits = word;
                std::uint64_t factor = 1;
                if (!digits.empty() && (digits.back() == 'k' || digits.back() == 'M')) {
                    factor = digits.back() == 'k' ? 1000 : 1000000;
                    digits.pop_back();
                }
                std::uint64_t value = 0;
                const auto [end, error] =
                    std::from_chars(digits.data(), digits.data() + digits.size(), value);
                if (error != std::errc{} || end != digits.data() + digits.size() || value == 0 ||
                    value * factor > std::numeric_limits<std::int32_t>::max()) {
                    return "expected a count like 1000, 10k or 1M, found " + quote_token(word);
                }
                word = std::to_string(value * factor);
                return {};
            },
            ""};
}

// How many rounds the lab measures: from 1 to kMostRounds.
constexpr unsigned kMostRounds = 1000;
CLI::Validator round_count() {
    return {[](const std::string& word) -> std::string {
                unsigned value = 0;
                const auto [end, error] =
                    std::from_chars(word.data(), word.data() + word.size(), value);
                if (error != std::errc{} || end != word.data() + word.size() || value == 0 ||
                    value > kMostRounds) {
                    return "expected a number of rounds from 1 to " + std::to_string(kMostRounds) +
                           ", found " + quote_token(word);
                }
                return {};
            },
            ""};
}

// A CPU this process may run on, as sched_getaffinity lists them.
CLI::Validator allowed_cpu() {
    return {[](const std::string& word) -> std::string {
                cpu_set_t allowed;
                CPU_ZERO(&allowed);
                sched_getaffinity(0, sizeof allowed, &allowed);
                std::string list;
                for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
                    if (CPU_ISSET(static_cast<std::size_t>(cpu), &allowed)) {
                        if (!list.empty()) {
                            list += ',';
                        }
                        list += std::to_string(cpu);
                    }
                }
                int cpu = 0;
                const auto [end, error] =
                    std::from_chars(word.data(), word.data() + word.size(), cpu);
                if (error != std::errc{} || end != word.data() + word.size() || cpu < 0 ||
                    cpu >= CPU_SETSIZE || !CPU_ISSET(static_cast<std::size_t>(cpu), &allowed)) {
                    return "expected one of this process's CPUs (" + list + "), found " +
                           quote_token(word);
                }
                return {};
            },
            ""};
}

CLI::Validator accel_name() {
    return {[](const std::string& name) -> std::string {
                return accel_kind_from_name(name)
                           ? std::string()
                           : "unknown intersection method " + quote_token(name) +
                                 " (brute, octree, seads, bvh, embree)";
            },
            ""};
}

}  // namespace

void add_lab_options(CLI::App& app, LabOptions& o) {
    // Every option acts when it is read, so the command line's order decides (see --quick).
    app.add_flag_callback(
           "--quick",
           [&o] {
               o.sizes = {1000, 10000};
               o.seconds_per_run = 0.1;
               o.brute_force_tests = 2e7;
           },
           "1k and 10k triangles, shorter runs")
        ->trigger_on_parse();
    app.add_option("--sizes", o.sizes,
                   "triangle counts, e.g. 1k,10k,100k,1M (the default) or 10M (no brute force)")
        ->type_name("LIST")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->transform(count())
        ->trigger_on_parse();
    app.add_option("--meshes", o.meshes, "sphere,soup,twocubes (the default)")
        ->type_name("LIST")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(CLI::IsMember({"sphere", "soup", "twocubes"}).description(""))
        ->trigger_on_parse();
    app.add_option_function<std::vector<std::string>>(
           "--accels",
           [&o](const std::vector<std::string>& names) {
               o.accels.clear();
               for (const std::string& name : names) {
                   o.accels.push_back(*accel_kind_from_name(name));
               }
           },
           "brute,octree,seads,bvh,embree (the default; missing ones are skipped)")
        ->type_name("LIST")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(accel_name())
        ->trigger_on_parse();
    app.add_option("--rounds", o.rounds,
                   "measure every method N times, in turn forward and backward, and print its "
                   "shares of Embree's figures as median (range) (default 1)")
        ->type_name("N")
        ->check(round_count())
        ->trigger_on_parse();
    app.add_option("--threads", o.threads, "threads for the all-cores runs (default: all)")
        ->type_name("N")
        ->transform(count())
        ->trigger_on_parse();
    app.add_option("--seconds", o.seconds_per_run, "least time per measurement (default 0.3)")
        ->type_name("S")
        ->check(cli::number_above(0.0))
        ->trigger_on_parse();
    app.add_option("--seads-side", o.seads_side,
                   "SEADS voxels a side (default: the suggested size per mesh)")
        ->type_name("N")
        ->transform(count())
        ->trigger_on_parse();
    app.add_option("--octree-depth", o.octree_depth,
                   "octree depth (default: the suggested depth per mesh)")
        ->type_name("N")
        ->transform(count())
        ->trigger_on_parse();
    app.add_option("--csv", o.csv_file, "also write the table as CSV")
        ->type_name("FILE")
        ->trigger_on_parse();
    app.add_option("--svg", o.svg_file, "also draw rays/s against triangle count (log-log)")
        ->type_name("FILE")
        ->trigger_on_parse();
    app.add_option("--time-svg", o.time_svg_file,
                   "also draw ns per ray (one thread) against triangle count (log-log)")
        ->type_name("FILE")
        ->trigger_on_parse();
    app.add_option("--pin", o.pin_cpu,
                   "run the one-thread measurements on this CPU (builds and NT runs stay free)")
        ->type_name("CPU")
        ->check(allowed_cpu())
        ->trigger_on_parse();
    app.add_option("--source", o.source_dir, "the source tree, for scenes/twocubes.scn (default .)")
        ->type_name("DIR")
        ->trigger_on_parse();
}

}  // namespace rt::lab
