// The Embree 3 functions the embree intersection method calls, found in libembree3 the first time
// the method is wanted rather than linked: loading Embree and TBB would add about 5 ms to every
// start of rt, though only --accel embree and the lab use them.
#pragma once

#include <embree3/rtcore.h>

namespace rt {

/// Named as Embree names them; each typed from Embree's own header, so that none can drift.
/// (rtcInitIntersectContext is an inline in the header, not a function of the library.)
struct EmbreeFunctions {
    decltype(&::rtcAttachGeometry) rtcAttachGeometry = nullptr;
    decltype(&::rtcCommitGeometry) rtcCommitGeometry = nullptr;
    decltype(&::rtcCommitScene) rtcCommitScene = nullptr;
    decltype(&::rtcGetDeviceError) rtcGetDeviceError = nullptr;
    decltype(&::rtcIntersect1) rtcIntersect1 = nullptr;
    decltype(&::rtcIntersect8) rtcIntersect8 = nullptr;
    decltype(&::rtcNewDevice) rtcNewDevice = nullptr;
    decltype(&::rtcNewGeometry) rtcNewGeometry = nullptr;
    decltype(&::rtcNewScene) rtcNewScene = nullptr;
    decltype(&::rtcOccluded1) rtcOccluded1 = nullptr;
    decltype(&::rtcReleaseDevice) rtcReleaseDevice = nullptr;
    decltype(&::rtcReleaseGeometry) rtcReleaseGeometry = nullptr;
    decltype(&::rtcReleaseScene) rtcReleaseScene = nullptr;
    decltype(&::rtcSetDeviceMemoryMonitorFunction) rtcSetDeviceMemoryMonitorFunction = nullptr;
    decltype(&::rtcSetNewGeometryBuffer) rtcSetNewGeometryBuffer = nullptr;
};

/// Loads libembree3.so.3 and its functions the first time (thread-safe) and keeps them for the
/// rest of the run. Throws Error naming the library or function that cannot be found; the next
/// call tries again.
const EmbreeFunctions& embree_functions();

}  // namespace rt
