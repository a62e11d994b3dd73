#include "bench_arguments.h"

#include <charconv>
#include <string_view>

#include "rt/core/error.h"

namespace rt::bench {

namespace {

// The value of `--name VALUE` or `--name=VALUE` at args[i], advancing i past it; none if args[i]
// is not that switch.
std::optional<std::string> take_value(const std::vector<std::string>& args, std::size_t& i,
                                      std::string_view name) {
    const std::string& arg = args[i];
    if (arg == name) {
        if (i + 1 >= args.size()) {
            throw UsageError(std::string(name) + ": a value must follow");
        }
        return args[++i];
    }
    if (arg.size() > name.size() && arg.compare(0, name.size(), name) == 0 &&
        arg[name.size()] == '=') {
        return arg.substr(name.size() + 1);
    }
    return std::nullopt;
}

int positive_count(const std::string& text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value < 1) {
        throw UsageError("--repeat: expected a whole number of at least 1, found '" + text + "'");
    }
    return value;
}

}  // namespace

BenchArguments split_bench_arguments(const std::vector<std::string>& args) {
    BenchArguments out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (const std::optional<std::string> repeat = take_value(args, i, "--repeat")) {
            out.repeat = positive_count(*repeat);
        } else if (const std::optional<std::string> csv = take_value(args, i, "--csv")) {
            out.csv = *csv;
        } else {
            out.rt_args.push_back(args[i]);
        }
    }
    return out;
}

std::string bench_usage() {
    return "usage: rt_scene_bench [--repeat N] [--csv FILE] SCENE [rt switches]\n"
           "  Loads SCENE once, builds its accelerator once and renders it N times (default 5)\n"
           "  through the library, writing no picture; prints the median and minimum wall time\n"
           "  per render and rays per second. rt's own switches apply: --threads N, --accel NAME,\n"
           "  -Ds, -L and the rest (see rt --help). --csv appends one row of results to FILE.\n";
}

}  // namespace rt::bench
