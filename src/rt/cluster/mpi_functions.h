// The MPI functions and handles a cluster run uses, found in libmpi when rt finds itself under
// mpirun rather than linked: loading OpenMPI (with open-rte, open-pal, hwloc, libevent) would add
// about 5 ms to every start of rt, though only runs under mpirun use it. Only mpi_world.cpp
// includes this header; nothing else in rt sees MPI.
#pragma once

#include <mpi.h>

namespace rt::cluster {

/// The functions are named as MPI names them, each typed from MPI's own header so that none can
/// drift. The handles are what OpenMPI's macros of the same names (MPI_COMM_WORLD, MPI_BYTE,
/// MPI_ERRORS_RETURN) stand for: addresses of libmpi's global objects, found by name as the
/// functions are. (MPI_STATUS_IGNORE, MPI_ANY_SOURCE and the like are plain constants.)
struct MpiFunctions {
    decltype(&::MPI_Comm_rank) MPI_Comm_rank = nullptr;
    decltype(&::MPI_Comm_set_errhandler) MPI_Comm_set_errhandler = nullptr;
    decltype(&::MPI_Comm_size) MPI_Comm_size = nullptr;
    decltype(&::MPI_Error_string) MPI_Error_string = nullptr;
    decltype(&::MPI_Finalize) MPI_Finalize = nullptr;
    decltype(&::MPI_Get_count) MPI_Get_count = nullptr;
    decltype(&::MPI_Init_thread) MPI_Init_thread = nullptr;
    decltype(&::MPI_Iprobe) MPI_Iprobe = nullptr;
    decltype(&::MPI_Recv) MPI_Recv = nullptr;
    decltype(&::MPI_Send) MPI_Send = nullptr;

    MPI_Comm comm_world = nullptr;           ///< MPI_COMM_WORLD
    MPI_Datatype byte = nullptr;             ///< MPI_BYTE
    MPI_Errhandler errors_return = nullptr;  ///< MPI_ERRORS_RETURN
};

/// Loads libmpi.so.40 and its functions the first time (thread-safe) and keeps them for the rest
/// of the run. Throws Error naming the library or symbol that cannot be found; the next call
/// tries again.
const MpiFunctions& mpi_functions();

}  // namespace rt::cluster
