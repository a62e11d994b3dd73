// `mpirun -n K rt SCENE [switches]`: rt's run() on every process of an MPI job. Rank 0 reads the
// command line's outputs, coordinates and renders too; every rank renders the rows it is handed,
// a few at a time, on its --threads threads; rank 0 gathers the rows and writes the same files,
// pixel for pixel, as a single process (docs/distributed.md).
#pragma once

#include "rt/app/run.h"

namespace rt::cluster {

/// Runs options on this process of the MPI job (MPI is started and ended here). On rank 0 it
/// reports through console and returns as run() does; a failure anywhere, or a signal, throws a
/// ClusterError on rank 0 that names the rank, and no output is written. On the other ranks it
/// prints nothing and returns Finished (their errors go to rank 0).
RunOutcome run_in_cluster(const Options& options, const RunConsole& console, int& argc,
                          char**& argv);

}  // namespace rt::cluster
