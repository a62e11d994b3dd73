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
    return closest_hit_in_buffer(scene_, buffer_, space, t, *pixel, counters);
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
