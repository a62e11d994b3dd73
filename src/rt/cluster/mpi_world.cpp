#include "rt/cluster/mpi_world.h"

#include <cstdlib>
#include <string>

#include "rt/cluster/cluster_error.h"

#include <fmt/format.h>

#include <mpi.h>

namespace rt::cluster {

namespace {

void check(int code, const char* what) {
    if (code == MPI_SUCCESS) {
        return;
    }
    char text[MPI_MAX_ERROR_STRING] = {};
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw ClusterError(fmt::format("MPI failed in {}: {}", what, std::string(text, length)));
}

}  // namespace

bool started_by_mpi_launcher() {
    // OpenMPI's mpirun, MPICH's hydra and Slurm's srun (PMI) name the job's size.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(name) != nullptr) {  // NOLINT(concurrency-mt-unsafe)
            return true;
        }
    }
    return false;
}

MpiWorld::MpiWorld(int& argc, char**& argv) {
    // rt's messages are rows of pixels, a few kilobytes each, so OpenMPI's ob1 layer (shared
    // memory on a machine, TCP between machines) carries them as fast as UCX would; probing UCX
    // at start costs 0.2 s of every run (docs/distributed.md). A choice the user made, with
    // `mpirun --mca pml ucx` or OMPI_MCA_pml, stands.
    ::setenv("OMPI_MCA_pml", "ob1", 0);  // NOLINT(concurrency-mt-unsafe): before any thread
    int provided = 0;
    if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        throw ClusterError("MPI could not start (MPI_Init_thread failed)");
    }
    // Errors come back as codes, so that rank 0 can name what failed instead of MPI aborting.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
    if (provided < MPI_THREAD_FUNNELED) {
        throw ClusterError("this MPI library cannot run beside threads (MPI_THREAD_FUNNELED)");
    }
}

MpiWorld::~MpiWorld() {
    if (finalize_) {
        MPI_Finalize();
    }
}

void MpiWorld::send(int to, int tag, std::span<const std::byte> bytes) {
    check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD),
          "MPI_Send");
}

std::optional<MpiWorld::Message> MpiWorld::poll() {
    int arrived = 0;
    MPI_Status status{};
    check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status), "MPI_Iprobe");
    if (arrived == 0) {
        return std::nullopt;
    }
    int count = 0;
    check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
    Message message{status.MPI_SOURCE, status.MPI_TAG,
                    std::vector<std::byte>(static_cast<std::size_t>(count))};
    check(MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG,
                   MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv");
    return message;
}

}  // namespace rt::cluster
