#include "rt/accel/zbuffer/zbuffer_first_hits.h"

#include <chrono>

#include "rt/accel/lane_exact_hit.h"
#include "rt/geometry/ray_polygon.h"

#include <fmt/format.h>

namespace rt {

namespace {

ItemBuffer timed_buffer(const Scene& scene, const Camera& view, const ZBufferSettings& settings,
                        double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    ItemBuffer buffer(scene, view, settings);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return buffer;
}

// No hit on a polygon whose reach is `nearest` from the eye is nearer than this t, for a ray
// starting `from_eye` from the eye: |Y - O| >= |Y - E| - |O - E| (item_buffer.cpp). Rounded
// down generously.
double lowest_t(double nearest, double from_eye, double direction_length) {
    return (nearest * (1.0 - 1e-12) - from_eye * (1.0 + 1e-12)) / direction_length * (1.0 - 1e-12);
}

}  // namespace

ZBufferFirstHits::ZBufferFirstHits(const Scene& scene, const Camera& view,
                                   const Accelerator& fallback, const ZBufferSettings& settings)
    : scene_(scene),
      fallback_(fallback),
      buffer_(timed_buffer(scene, view, settings, build_seconds_)),
      name_("z-buffer first hits over " + std::string(fallback.name())) {}

std::optional<Hit> ZBufferFirstHits::eye_ray_closest_hit(const Ray& ray, Interval t,
                                                         TraceCounters& counters) const {
    const std::optional<EyeRayPixel> pixel = buffer_.pixel_of(ray, t);
    const RaySpace space(ray);
    if (!pixel || !space.valid()) {
        return fallback_.eye_ray_closest_hit(ray, t, counters);
    }
    const double direction_length = length(ray.direction);
    ClosestHitSoFar nearest(t);
    for (const std::uint32_t rank : buffer_.candidates(pixel->x, pixel->y)) {
        // Strictly beyond: a polygon that might still tie the best t could have a lower id.
        if (nearest.best() &&
            lowest_t(buffer_.nearest(rank), pixel->from_eye, direction_length) > nearest.reach()) {
            break;
        }
        const std::uint32_t id = buffer_.polygon(rank);
        if (leaves_polygon(ray, id)) {
            continue;
        }
        ++counters.polygon_tests;
        // The same t brute force computes: the interval only decides whether it counts.
        if (const std::optional<double> hit =
                intersect_polygon(space, scene_.polygon_view(id), nearest.search_interval())) {
            nearest.offer(*hit, id);
        }
    }
    return nearest.best();
}

std::size_t ZBufferFirstHits::memory_bytes() const {
    return buffer_.memory_bytes() + fallback_.memory_bytes();
}

ZBufferStatistics ZBufferFirstHits::statistics() const {
    ZBufferStatistics s;
    s.active = buffer_.active();
    s.inactive_reason = buffer_.inactive_reason();
    s.polygons_in_view = buffer_.polygons_in_view();
    s.entries = buffer_.entries();
    s.longest_list = buffer_.longest_list();
    s.memory_bytes = buffer_.memory_bytes();
    s.build_seconds = build_seconds_;
    return s;
}

std::vector<std::string> describe(const ZBufferStatistics& s) {
    if (!s.active) {
        return {"z-buffer off: " + s.inactive_reason};
    }
    return {fmt::format(
        "z-buffer: {} polygons in view, {} pixel entries (at most {} in a pixel), "
        "{} bytes, built in {:.3f} ms",
        s.polygons_in_view, s.entries, s.longest_list, s.memory_bytes, 1e3 * s.build_seconds)};
}

std::unique_ptr<ZBufferFirstHits> make_zbuffer_first_hits(const Scene& scene, const Camera& view,
                                                          const Accelerator& fallback,
                                                          const ZBufferSettings& settings) {
    return std::make_unique<ZBufferFirstHits>(scene, view, fallback, settings);
}

}  // namespace rt
