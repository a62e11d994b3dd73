// The Assimp functions the model reader calls (its C API), found in libassimp the first time a
// model is read rather than linked: loading Assimp and the libraries it needs (draco, minizip...)
// would add about 7.5 ms to every start of rt, though only scenes with models use it.
#pragma once

#include <assimp/cimport.h>
#include <assimp/material.h>

namespace rt {

/// Named as Assimp names them; each typed from Assimp's own header, so that none can drift. The
/// C++ API (Assimp::Importer, aiMaterial::Get) is not used: its functions would be linked.
struct AssimpFunctions {
    decltype(&::aiAttachLogStream) aiAttachLogStream = nullptr;
    decltype(&::aiDetachLogStream) aiDetachLogStream = nullptr;
    decltype(&::aiEnableVerboseLogging) aiEnableVerboseLogging = nullptr;
    decltype(&::aiGetErrorString) aiGetErrorString = nullptr;
    /// aiMaterial::Get(key, aiColor3D&) calls this one.
    decltype(&::aiGetMaterialColor) aiGetMaterialColor = nullptr;
    /// aiMaterial::GetName() and Get(key, aiString&) call this one.
    decltype(&::aiGetMaterialString) aiGetMaterialString = nullptr;
    decltype(&::aiImportFileExWithProperties) aiImportFileExWithProperties = nullptr;
    decltype(&::aiIsExtensionSupported) aiIsExtensionSupported = nullptr;
    decltype(&::aiReleaseImport) aiReleaseImport = nullptr;
};

/// Loads libassimp.so.5 and its functions the first time (thread-safe) and keeps them for the
/// rest of the run. Throws Error naming the library or function that cannot be found; the next
/// call tries again.
const AssimpFunctions& assimp_functions();

}  // namespace rt
