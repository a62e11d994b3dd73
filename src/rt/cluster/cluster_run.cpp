#include "rt/cluster/cluster_run.h"

#include "rt/app/interrupt.h"
#include "rt/app/resume.h"
#include "rt/cluster/cluster_error.h"
#include "rt/cluster/coordinator.h"
#include "rt/cluster/helper.h"
#include "rt/cluster/mpi_world.h"

#include <fmt/format.h>

namespace rt::cluster {

namespace {

// What every rank must agree on, checked by rank 0 against its own before any row is shared.
std::string identity(const Options& options) {
    return encode_arguments(options.render_arguments);
}

// A helping rank prints nothing and writes nothing: rank 0 speaks for the job.
Options helper_options(Options options) {
    options.no_gro = true;
    options.outputs.clear();
    options.no_window = true;
    options.quiet = true;
    return options;
}

RunOutcome run_as_coordinator(const Options& options, const RunConsole& console, MpiWorld& world) {
    Coordinator coordinator(world, identity(options));
    try {
        const RunOutcome outcome =
            run(options, console,
                [&](const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                    RenderObserver& observer, RenderStatistics& statistics) {
                    return std::optional<Film>(
                        coordinator.render(scene, accel, settings, observer, statistics));
                });
        coordinator.finish();  // -r, -w, -doi: nothing was shared; release the ranks
        return outcome;
    } catch (...) {
        if (interrupt_requested()) {
            world.abandon();  // mpirun is tearing the job down: the others may be gone
        } else {
            coordinator.stop_everyone();
        }
        throw;
    }
}

RunOutcome run_as_helper(const Options& options, MpiWorld& world) {
    Helper helper(world, identity(options));
    try {
        run(helper_options(options), RunConsole{},
            [&](const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                RenderObserver& /*observer*/, RenderStatistics& /*statistics*/) {
                helper.render(scene, accel, settings);
                return std::optional<Film>();
            });
        helper.finish();
    } catch (const std::exception& e) {
        if (interrupt_requested()) {
            world.abandon();
        } else {
            helper.fail(e.what());
        }
    }
    return RunOutcome::Finished;
}

}  // namespace

RunOutcome run_in_cluster(const Options& options, const RunConsole& console, int& argc,
                          char**& argv) {
    MpiWorld world(argc, argv);
    if (world.size() == 1) {
        return run(options, console);
    }
    return world.rank() == 0 ? run_as_coordinator(options, console, world)
                             : run_as_helper(options, world);
}

}  // namespace rt::cluster
