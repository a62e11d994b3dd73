// The scene benchmark's command line: its own options, and everything else handed to rt's parser.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace rt::bench {

struct BenchArguments {
    int repeat = 5;                  ///< --repeat N: renders to time
    std::optional<std::string> csv;  ///< --csv FILE: append one row of results
    bool replay = false;             ///< --replay: record one render, time its queries alone
    std::vector<std::string> replay_accels;  ///< --replay-accels LIST: also through these
    std::vector<std::string> rt_args;  ///< SCENE and rt's switches (--threads, --accel, -Ds...)
};

/// Declares --repeat N and --csv FILE (also --repeat=N, --csv=FILE) on app, writing into
/// arguments, and lets app keep every other argument, in order, for rt::parse_command_line
/// (take them with app.remaining() after parsing).
void add_bench_options(CLI::App& app, BenchArguments& arguments);

}  // namespace rt::bench
