#include "rt/cluster/mpi_functions.h"

#include "rt/core/shared_library.h"

// The handles below are found by OpenMPI's names, in the library of OpenMPI's soname.
#ifndef OPEN_MPI
#error "rt's cluster runs load OpenMPI's libmpi; this mpi.h is another MPI's"
#endif

namespace rt::cluster {

namespace {

// One of OpenMPI's predefined objects, as its header's macro would give it: the address of the
// global `name` as a handle of type Handle (a pointer to an opaque struct).
template <typename Handle>
Handle predefined(const SharedLibrary& library, const char* name) {
    return static_cast<Handle>(library.symbol(name));
}

MpiFunctions find_functions(const SharedLibrary& library) {
    MpiFunctions f;
// The member and the symbol have the function's name; the type comes from MPI's declaration.
#define RT_FIND(name) f.name = library.function<decltype(::name)>(#name)
    RT_FIND(MPI_Comm_rank);
    RT_FIND(MPI_Comm_set_errhandler);
    RT_FIND(MPI_Comm_size);
    RT_FIND(MPI_Error_string);
    RT_FIND(MPI_Finalize);
    RT_FIND(MPI_Get_count);
    RT_FIND(MPI_Init_thread);
    RT_FIND(MPI_Iprobe);
    RT_FIND(MPI_Recv);
    RT_FIND(MPI_Send);
#undef RT_FIND
    f.comm_world = predefined<MPI_Comm>(library, "ompi_mpi_comm_world");
    f.byte = predefined<MPI_Datatype>(library, "ompi_mpi_byte");
    f.errors_return = predefined<MPI_Errhandler>(library, "ompi_mpi_errors_return");
    return f;
}

}  // namespace

const MpiFunctions& mpi_functions() {
    // Global: OpenMPI loads its components (mca_*.so) with dlopen at MPI_Init, and they use
    // libmpi's symbols without naming libmpi among the libraries they need (mca_pml_ob1.so names
    // only libc), so libmpi's symbols are opened to them, as mpi4py does. OpenMPI 3.0 and later
    // find them even from a library opened RTLD_LOCAL (open-mpi/ompi#3705; Debian 12's 4.1
    // does), but nothing else rt loads could clash with them, so Global costs nothing. Never
    // closed: MPI cannot start twice in a process, and OpenMPI's threads and components may
    // outlive MPI_Finalize.
    static const SharedLibrary* const library =
        new SharedLibrary("libmpi.so.40", SymbolScope::Global);
    static const MpiFunctions functions = find_functions(*library);
    return functions;
}

}  // namespace rt::cluster
