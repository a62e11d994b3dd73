// A shared library opened while the program runs (dlopen) rather than linked: the optional ones
// (SDL2 for the window, Assimp for models, MPI under mpirun) cost every start of rt
// milliseconds of loading and relocating, though most runs never call them.
#pragma once

#include <string>

namespace rt {

/// Whether the symbols of a library opened later may bind to this library's (dlopen's RTLD_LOCAL
/// or RTLD_GLOBAL).
enum class SymbolScope {
    /// Its symbols are found only through symbol(): it cannot clash with anything.
    Local,
    /// Its symbols are open to every library loaded after it, as if the program had linked it.
    /// For a library that loads plugins of its own which use its symbols without linking it
    /// (OpenMPI's components use libmpi's; mpi4py opens libmpi so too).
    Global,
};

class SharedLibrary {
public:
    /// Opens the library by its soname ("libSDL2-2.0.so.0"), resolving every symbol now. Throws
    /// Error "cannot load NAME: <dlerror>" when it cannot.
    explicit SharedLibrary(std::string soname, SymbolScope scope = SymbolScope::Local);
    /// Closes it (dlclose): what came from it must not be used after.
    ~SharedLibrary();
    SharedLibrary(const SharedLibrary&) = delete;
    SharedLibrary& operator=(const SharedLibrary&) = delete;

    const std::string& soname() const { return soname_; }

    /// The address of the symbol `name` (a function or data). Throws Error "cannot find NAME in
    /// SONAME: <dlerror>".
    void* symbol(const char* name) const;

    /// The function `name` with the type `Function`, a function type: take it from the library's
    /// header (decltype(SDL_Init)) so that it cannot drift from the library's.
    template <typename Function>
    Function* function(const char* name) const {
        return reinterpret_cast<Function*>(symbol(name));
    }

private:
    std::string soname_;
    void* handle_ = nullptr;
};

}  // namespace rt
