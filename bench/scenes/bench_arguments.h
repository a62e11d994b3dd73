// The scene benchmark's command line: its own switches, and everything else handed to rt's parser.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt::bench {

struct BenchArguments {
    int repeat = 5;                    ///< --repeat N: renders to time
    std::optional<std::string> csv;    ///< --csv FILE: append one row of results
    std::vector<std::string> rt_args;  ///< SCENE and rt's switches (--threads, --accel, -Ds...)
};

/// Takes out --repeat N and --csv FILE (also --repeat=N, --csv=FILE); the rest is kept in order
/// for rt::parse_command_line. Throws rt::UsageError for a missing or bad value.
BenchArguments split_bench_arguments(const std::vector<std::string>& args);

/// What `rt_scene_bench --help` prints.
std::string bench_usage();

}  // namespace rt::bench
