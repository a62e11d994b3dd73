#include "rt/core/shared_library.h"

#include <string>
#include <utility>

#include "rt/core/error.h"

#include <dlfcn.h>

namespace rt {

namespace {

std::string last_dl_error() {
    const char* text = dlerror();  // NOLINT(concurrency-mt-unsafe): glibc keeps it per thread
    return text != nullptr ? text : "unknown error";
}

}  // namespace

SharedLibrary::SharedLibrary(std::string soname, SymbolScope scope) : soname_(std::move(soname)) {
    const int visibility = scope == SymbolScope::Global ? RTLD_GLOBAL : RTLD_LOCAL;
    handle_ = dlopen(soname_.c_str(), RTLD_NOW | visibility);
    if (handle_ == nullptr) {
        throw Error("cannot load " + soname_ + ": " + last_dl_error());
    }
}

SharedLibrary::~SharedLibrary() {
    dlclose(handle_);
}

void* SharedLibrary::symbol(const char* name) const {
    dlerror();  // clears an earlier error, so that the one below is this lookup's
    void* address = dlsym(handle_, name);
    if (address == nullptr) {
        throw Error("cannot find " + std::string(name) + " in " + soname_ + ": " + last_dl_error());
    }
    return address;
}

}  // namespace rt
