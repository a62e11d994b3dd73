#include "rt/accel/embree/embree_functions.h"

#include "rt/core/shared_library.h"

namespace rt {

namespace {

EmbreeFunctions find_functions(const SharedLibrary& library) {
    EmbreeFunctions f;
// The member and the symbol have the function's name; the type comes from Embree's declaration.
#define RT_FIND(name) f.name = library.function<decltype(::name)>(#name)
    RT_FIND(rtcAttachGeometry);
    RT_FIND(rtcCommitGeometry);
    RT_FIND(rtcCommitScene);
    RT_FIND(rtcGetDeviceError);
    RT_FIND(rtcIntersect1);
    RT_FIND(rtcIntersect8);
    RT_FIND(rtcNewDevice);
    RT_FIND(rtcNewGeometry);
    RT_FIND(rtcNewScene);
    RT_FIND(rtcOccluded1);
    RT_FIND(rtcReleaseDevice);
    RT_FIND(rtcReleaseGeometry);
    RT_FIND(rtcReleaseScene);
    RT_FIND(rtcSetDeviceMemoryMonitorFunction);
    RT_FIND(rtcSetNewGeometryBuffer);
#undef RT_FIND
    return f;
}

}  // namespace

const EmbreeFunctions& embree_functions() {
    // Never closed: TBB's worker threads, started by Embree, may outlive every device, and
    // unloading their code under them at exit would gain nothing.
    static const SharedLibrary* const library = new SharedLibrary("libembree3.so.3");
    static const EmbreeFunctions functions = find_functions(*library);
    return functions;
}

}  // namespace rt
