// The thin layer over MPI that a cluster run needs: start and end MPI, send a message, poll for
// one. Only the thread that made the MpiWorld calls it (MPI_THREAD_FUNNELED); the renderer's
// worker threads never touch MPI. Every MPI error becomes a ClusterError. libmpi is not linked:
// the first MpiWorld loads it (mpi_functions.h), so a run outside mpirun never does.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace rt::cluster {

struct MpiFunctions;

/// Whether an MPI launcher (mpirun, srun) started this process: only then does rt start MPI,
/// so that a plain `rt SCENE` never pays for it.
bool started_by_mpi_launcher();

/// The rank the launcher gave this process, from its environment, before MPI starts: what a rank
/// knows while it reads its command line. Nothing outside a launcher, or for a value that is not
/// a rank.
std::optional<int> launcher_rank();

class MpiWorld {
public:
    /// Loads libmpi and starts MPI. Throws ClusterError when libmpi cannot be loaded (naming it)
    /// or MPI cannot start.
    MpiWorld(int& argc, char**& argv);
    ~MpiWorld();
    MpiWorld(const MpiWorld&) = delete;
    MpiWorld& operator=(const MpiWorld&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }

    struct Message {
        int from = 0;
        int tag = 0;
        std::vector<std::byte> bytes;
    };

    void send(int to, int tag, std::span<const std::byte> bytes);
    /// The next message that has arrived from anyone, without waiting; nothing if none has.
    std::optional<Message> poll();

    /// The job is being torn down (a signal from mpirun): leave without MPI_Finalize, which
    /// would wait for processes that are gone.
    void abandon() { finalize_ = false; }

private:
    /// Throws a ClusterError naming `what` and MPI's words for `code` unless it is MPI_SUCCESS.
    void check(int code, const char* what) const;

    const MpiFunctions& mpi_;
    int rank_ = 0;
    int size_ = 1;
    bool finalize_ = true;
};

}  // namespace rt::cluster
