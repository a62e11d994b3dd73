#include "rt/scene/read/assimp_functions.h"

#include "rt/core/shared_library.h"

namespace rt {

namespace {

AssimpFunctions find_functions(const SharedLibrary& library) {
    AssimpFunctions f;
// The member and the symbol have the function's name; the type comes from Assimp's declaration.
#define RT_FIND(name) f.name = library.function<decltype(::name)>(#name)
    RT_FIND(aiAttachLogStream);
    RT_FIND(aiDetachLogStream);
    RT_FIND(aiEnableVerboseLogging);
    RT_FIND(aiGetErrorString);
    RT_FIND(aiGetMaterialColor);
    RT_FIND(aiGetMaterialString);
    RT_FIND(aiImportFileExWithProperties);
    RT_FIND(aiIsExtensionSupported);
    RT_FIND(aiReleaseImport);
#undef RT_FIND
    return f;
}

}  // namespace

const AssimpFunctions& assimp_functions() {
    // Never closed: Assimp's process-wide logger and importer registry live in it, and unloading
    // it at exit would gain nothing.
    static const SharedLibrary* const library = new SharedLibrary("libassimp.so.5");
    static const AssimpFunctions functions = find_functions(*library);
    return functions;
}

}  // namespace rt
