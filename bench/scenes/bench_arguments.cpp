#include "bench_arguments.h"

#include "command_line/command_line.h"

namespace rt::bench {

void add_bench_options(CLI::App& app, BenchArguments& arguments) {
    // rt's switches pass through; only --help is ours, so that no -h... of rt's is taken for it.
    app.allow_extras();
    app.set_help_flag("--help", "Print this help message and exit");
    app.add_option("--repeat", arguments.repeat, "renders to time (default 5)")
        ->type_name("N")
        ->transform(cli::whole_number_at_least(1));
    app.add_option("--csv", arguments.csv, "append one row of results to FILE")->type_name("FILE");
    app.add_flag("--replay", arguments.replay,
                 "also record one render's intersection queries (on one thread) and time them "
                 "alone, as many times as --repeat, on the renders' threads");
    app.add_option("--replay-accels", arguments.replay_accels,
                   "replay them through these methods too (brute,octree,seads,bvh,embree), each "
                   "in the stack rt's switches describe; implies --replay")
        ->type_name("LIST")
        ->delimiter(',')
        ->allow_extra_args(false)  // the scene and rt's switches follow
        ->check(CLI::IsMember({"brute", "octree", "seads", "bvh", "embree"}).description(""));
}

}  // namespace rt::bench
