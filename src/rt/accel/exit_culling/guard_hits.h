// The answer for a ray the leaving table (leaving_table.h) confines to a few of its polygon's
// guards: brute force's answer, from those polygons alone. Every other polygon is certainly
// missed, so testing only the candidates with the same exact test, the same interval and the same
// tie rule (hit.h) gives brute force's hit bit for bit, without a walk through the structure.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "rt/accel/accelerator.h"
#include "rt/accel/hit.h"
#include "rt/core/ray.h"
#include "rt/scene/scene.h"

namespace rt {

/// The nearest hit on one of `polygons` with t strictly inside the interval; equal t goes to the
/// lowest polygon id. Counts its exact tests in counters.polygon_tests.
std::optional<Hit> closest_hit_among(const Scene& scene, const Ray& ray, Interval t,
                                     std::span<const std::uint32_t> polygons,
                                     TraceCounters& counters);

/// Whether the ray hits any of `polygons` with t strictly inside the interval.
bool any_hit_among(const Scene& scene, const Ray& ray, Interval t,
                   std::span<const std::uint32_t> polygons, TraceCounters& counters);

}  // namespace rt
