#include "rt/accel/exit_culling/exit_culling.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

namespace rt {

namespace {

constexpr std::size_t kViolationsKept = 10;
constexpr std::uint32_t kAllLanes = (1u << kPacketSize) - 1u;

ExitCullingTable timed_table(const Scene& scene, const ExitCullingSettings& settings,
                             double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    const int resolution = settings.grid_resolution > 0
                               ? settings.grid_resolution
                               : default_exit_culling_resolution(scene.polygons.size());
    ExitCullingTable table(scene, resolution, settings.bins_per_side, settings.build_threads);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return table;
}

}  // namespace

int default_exit_culling_resolution(std::size_t polygon_count) {
    const double guess = 2.0 * std::cbrt(static_cast<double>(polygon_count));
    return static_cast<int>(std::clamp(std::round(guess), 4.0, 8.0));
}

ExitCulling::ExitCulling(const Scene& scene, std::unique_ptr<Accelerator> wrapped,
                         const ExitCullingSettings& settings)
    : wrapped_(std::move(wrapped)),
      table_(timed_table(scene, settings, build_seconds_)),
      check_culled_(settings.check_culled),
      name_("exit culling over " + std::string(wrapped_->name())) {}

std::optional<Hit> ExitCulling::closest_hit(const Ray& ray, Interval t,
                                            TraceCounters& counters) const {
    if (!culls(ray, t)) {
        return wrapped_->closest_hit(ray, t, counters);
    }
    ++counters.culled_exits;
    if (check_culled_) {
        TraceCounters ignored;
        std::optional<Hit> truth = wrapped_->closest_hit(ray, t, ignored);
        record_if_violated(ray, truth.has_value());
        return truth;  // a wrong cull is reported, but the picture stays right
    }
    return std::nullopt;
}

bool ExitCulling::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    if (!culls(ray, t)) {
        return wrapped_->occluded(ray, t, counters);
    }
    ++counters.culled_exits;
    if (check_culled_) {
        TraceCounters ignored;
        const bool truth = wrapped_->occluded(ray, t, ignored);
        record_if_violated(ray, truth);
        return truth;
    }
    return false;
}

std::uint32_t ExitCulling::culled_lanes(const RayPacket& packet) const {
    std::uint32_t culled = 0;
    for (std::uint32_t a = packet.active & kAllLanes; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        culled |= culls(packet.rays[lane], packet.t[lane]) ? 1u << lane : 0u;
    }
    return culled;
}

void ExitCulling::closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                     TraceCounters& counters) const {
    const std::uint32_t culled = culled_lanes(packet);
    const std::uint32_t passed = packet.active & kAllLanes & ~culled;
    if (culled == 0) {
        wrapped_->closest_hit_packet(packet, hits, counters);
        return;
    }
    if (passed != 0) {
        RayPacket rest = packet;
        rest.active = passed;
        wrapped_->closest_hit_packet(rest, hits, counters);
    }
    counters.culled_exits += static_cast<std::uint64_t>(std::popcount(culled));
    for (std::uint32_t a = culled; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        hits[lane] = std::nullopt;
        if (check_culled_) {  // as closest_hit checks it, one ray at a time
            TraceCounters ignored;
            hits[lane] = wrapped_->closest_hit(packet.rays[lane], packet.t[lane], ignored);
            record_if_violated(packet.rays[lane], hits[lane].has_value());
        }
    }
}

std::uint32_t ExitCulling::occluded_packet(const RayPacket& packet, TraceCounters& counters) const {
    const std::uint32_t culled = culled_lanes(packet);
    const std::uint32_t passed = packet.active & kAllLanes & ~culled;
    if (culled == 0) {
        return wrapped_->occluded_packet(packet, counters);
    }
    std::uint32_t blocked = 0;
    if (passed != 0) {
        RayPacket rest = packet;
        rest.active = passed;
        blocked = wrapped_->occluded_packet(rest, counters);
    }
    counters.culled_exits += static_cast<std::uint64_t>(std::popcount(culled));
    for (std::uint32_t a = culled; check_culled_ && a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        TraceCounters ignored;
        const bool truth = wrapped_->occluded(packet.rays[lane], packet.t[lane], ignored);
        record_if_violated(packet.rays[lane], truth);
        blocked |= truth ? 1u << lane : 0u;
    }
    return blocked;
}

void ExitCulling::record_if_violated(const Ray& ray, bool violated) const {
    checked_.fetch_add(1, std::memory_order_relaxed);
    if (!violated) {
        return;
    }
    violations_.fetch_add(1, std::memory_order_relaxed);
    const std::lock_guard lock(violations_mutex_);
    if (first_violations_.size() < kViolationsKept) {
        first_violations_.push_back(ray);
    }
}

std::size_t ExitCulling::memory_bytes() const {
    return table_.memory_bytes() + wrapped_->memory_bytes();
}

ExitCullingStatistics ExitCulling::statistics() const {
    ExitCullingStatistics s;
    s.grid_resolution = table_.resolution();
    s.bins_per_side = table_.bins_per_side();
    s.regions = static_cast<std::size_t>(s.grid_resolution) * s.grid_resolution * s.grid_resolution;
    s.occupied_cells = table_.occupied_cells();
    s.empty_fraction = table_.empty_fraction();
    s.memory_bytes = table_.memory_bytes();
    s.build_seconds = build_seconds_;
    s.checking = check_culled_;
    s.checked = checked_.load();
    s.violations = violations_.load();
    const std::lock_guard lock(violations_mutex_);
    s.first_violations = first_violations_;
    return s;
}

std::vector<std::string> describe(const ExitCullingStatistics& s) {
    std::vector<std::string> lines;
    lines.push_back(fmt::format(
        "exit culling: {}^3 cells ({} occupied) x 6x{}x{} direction bins, {:.1f}% empty, "
        "{} bytes, built in {:.3f} ms",
        s.grid_resolution, s.occupied_cells, s.bins_per_side, s.bins_per_side,
        100.0 * s.empty_fraction, s.memory_bytes, 1e3 * s.build_seconds));
    if (s.checking) {
        lines.push_back(
            fmt::format("exit culling check (-de): {} culled rays re-traced, {} hit "
                        "something",
                        s.checked, s.violations));
        for (const Ray& r : s.first_violations) {
            lines.push_back(fmt::format(
                "  wrongly culled: origin ({:.17g}, {:.17g}, {:.17g}) direction ({:.17g}, "
                "{:.17g}, {:.17g})",
                r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z));
        }
    }
    return lines;
}

}  // namespace rt
