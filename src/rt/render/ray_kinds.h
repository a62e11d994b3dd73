// The kinds of rays a render traces, each with its own counters, so that -p can say where the
// time goes (manual Appendix -p: "various internal metrics").
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "rt/accel/accelerator.h"

namespace rt {

enum class RayKind : std::size_t {
    Eye,
    Reflected,
    Refracted,
    Diffuse,
    ShadowFeeler,
    Probe,
    Random
};
constexpr std::size_t kRayKinds = 7;

constexpr std::string_view ray_kind_name(RayKind kind) {
    constexpr std::array<std::string_view, kRayKinds> kNames{
        "eye", "reflected", "refracted", "diffuse", "shadow feeler", "probe", "random"};
    return kNames[static_cast<std::size_t>(kind)];
}

/// Counters per kind of ray.
struct KindCounters {
    std::array<TraceCounters, kRayKinds> kinds{};

    TraceCounters& operator[](RayKind kind) { return kinds[static_cast<std::size_t>(kind)]; }
    const TraceCounters& operator[](RayKind kind) const {
        return kinds[static_cast<std::size_t>(kind)];
    }
    KindCounters& operator+=(const KindCounters& other) {
        for (std::size_t k = 0; k < kRayKinds; ++k) {
            kinds[k] += other.kinds[k];
        }
        return *this;
    }
    TraceCounters total() const {
        TraceCounters sum;
        for (const TraceCounters& c : kinds) {
            sum += c;
        }
        return sum;
    }
};

}  // namespace rt
