#include "rt/cluster/mpi_world.h"

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

#include "rt/cluster/cluster_error.h"
#include "rt/cluster/mpi_functions.h"

#include <fmt/format.h>

namespace rt::cluster {

namespace {

// libmpi, loaded now: only a process an MPI launcher started gets here.
const MpiFunctions& load_mpi() {
    try {
        return mpi_functions();
    } catch (const Error& e) {
        throw ClusterError(
            fmt::format("{} (OpenMPI's library, which a run under mpirun needs)", e.what()));
    }
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

std::optional<int> launcher_rank() {
    if (!started_by_mpi_launcher()) {
        return std::nullopt;
    }
    // OpenMPI's mpirun, PMIx (OpenMPI 5, Slurm) and PMI (MPICH's hydra, Slurm).
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
        const char* value = std::getenv(name);  // NOLINT(concurrency-mt-unsafe)
        if (value == nullptr) {
            continue;
        }
        int rank = -1;
        const char* end = value + std::strlen(value);
        const auto [at, error] = std::from_chars(value, end, rank);
        if (error == std::errc() && at == end && at != value && rank >= 0) {
            return rank;
        }
        return std::nullopt;
    }
    return std::nullopt;
}

MpiWorld::MpiWorld(int& argc, char**& argv) : mpi_(load_mpi()) {
    // rt's messages are rows of pixels, a few kilobytes each, so OpenMPI's ob1 layer (shared
    // memory on a machine, TCP between machines) carries them as fast as UCX would; probing UCX
    // at start costs 0.2 s of every run (docs/distributed.md). A choice the user made, with
    // `mpirun --mca pml ucx` or OMPI_MCA_pml, stands.
    ::setenv("OMPI_MCA_pml", "ob1", 0);  // NOLINT(concurrency-mt-unsafe): before any thread
    int provided = 0;
    if (mpi_.MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        throw ClusterError("MPI could not start (MPI_Init_thread failed)");
    }
    // Errors come back as codes, so that rank 0 can name what failed instead of MPI aborting.
    mpi_.MPI_Comm_set_errhandler(mpi_.comm_world, mpi_.errors_return);
    check(mpi_.MPI_Comm_rank(mpi_.comm_world, &rank_), "MPI_Comm_rank");
    check(mpi_.MPI_Comm_size(mpi_.comm_world, &size_), "MPI_Comm_size");
    if (provided < MPI_THREAD_FUNNELED) {
        throw ClusterError("this MPI library cannot run beside threads (MPI_THREAD_FUNNELED)");
    }
}

void MpiWorld::check(int code, const char* what) const {
    if (code == MPI_SUCCESS) {
        return;
    }
    char text[MPI_MAX_ERROR_STRING] = {};
    int length = 0;
    mpi_.MPI_Error_string(code, text, &length);
    throw ClusterError(fmt::format("MPI failed in {}: {}", what, std::string(text, length)));
}

MpiWorld::~MpiWorld() {
    if (finalize_) {
        mpi_.MPI_Finalize();
    }
}

void MpiWorld::send(int to, int tag, std::span<const std::byte> bytes) {
    check(mpi_.MPI_Send(bytes.data(), static_cast<int>(bytes.size()), mpi_.byte, to, tag,
                        mpi_.comm_world),
          "MPI_Send");
}

std::optional<MpiWorld::Message> MpiWorld::poll() {
    int arrived = 0;
    MPI_Status status{};
    check(mpi_.MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, mpi_.comm_world, &arrived, &status),
          "MPI_Iprobe");
    if (arrived == 0) {
        return std::nullopt;
    }
    int count = 0;
    check(mpi_.MPI_Get_count(&status, mpi_.byte, &count), "MPI_Get_count");
    Message message{status.MPI_SOURCE, status.MPI_TAG,
                    std::vector<std::byte>(static_cast<std::size_t>(count))};
    check(mpi_.MPI_Recv(message.bytes.data(), count, mpi_.byte, status.MPI_SOURCE, status.MPI_TAG,
                        mpi_.comm_world, MPI_STATUS_IGNORE),
          "MPI_Recv");
    return message;
}

}  // namespace rt::cluster
