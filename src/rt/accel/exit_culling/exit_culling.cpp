#include "rt/accel/exit_culling/exit_culling.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>

#include "rt/accel/exit_culling/guard_hits.h"
#include "rt/geometry/ray_polygon.h"

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

// With the cell table's rounding allowances (its frame), made once.
LeavingTable timed_leaving_table(const Scene& scene, const ExitCullingTable& cells,
                                 const ExitCullingSettings& settings, double& seconds) {
    if (!settings.leaving_table) {
        return {};
    }
    const auto start = std::chrono::steady_clock::now();
    LeavingTable table(scene, cells.cells().frame(), settings.build_threads);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return table;
}

EyeCoverage timed_coverage(const Scene& scene, const ExitCullingTable& table,
                           const ExitCullingSettings& settings, double& seconds) {
    if (!settings.eye_coverage) {
        return {};
    }
    const auto start = std::chrono::steady_clock::now();
    EyeCoverage coverage(scene.view.camera(), scene.bounds(), table.cells());
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return coverage;
}

// The eye rays' item buffer, of tiles of kEyeTileSide pixels, for a scene of at most
// kMostEyeItemPolygons polygons whose eye rays the coverage serves; none otherwise.
std::unique_ptr<ItemBuffer> timed_eye_items(const Scene& scene, const EyeCoverage& coverage,
                                            const ExitCullingSettings& settings, double& seconds) {
    if (!settings.eye_items || !settings.answers || !coverage.active() ||
        scene.polygons.size() > kMostEyeItemPolygons) {
        return nullptr;
    }
    const auto start = std::chrono::steady_clock::now();
    ZBufferSettings tiles;
    tiles.tile_side = kEyeTileSide;
    tiles.max_bytes = kMostEyeItemBytes;
    auto items = std::make_unique<ItemBuffer>(scene, coverage.view().camera(), tiles);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return items->active() ? std::move(items) : nullptr;
}

}  // namespace

int default_exit_culling_resolution(std::size_t polygon_count) {
    const double guess = 2.0 * std::cbrt(static_cast<double>(polygon_count));
    return static_cast<int>(std::clamp(std::round(guess), 4.0, 8.0));
}

ExitCulling::ExitCulling(const Scene& scene, std::unique_ptr<Accelerator> wrapped,
                         const ExitCullingSettings& settings)
    : scene_(&scene),
      wrapped_(std::move(wrapped)),
      table_(timed_table(scene, settings, build_seconds_)),
      leaving_(timed_leaving_table(scene, table_, settings, build_seconds_)),
      eye_(timed_coverage(scene, table_, settings, build_seconds_)),
      eye_items_(timed_eye_items(scene, eye_, settings, build_seconds_)),
      answers_(settings.answers),
      check_culled_(settings.check_culled),
      scene_polygons_(scene.polygons.size()),
      name_("exit culling over " + std::string(wrapped_->name())) {}

std::optional<Hit> ExitCulling::closest_hit(const Ray& ray, Interval t,
                                            TraceCounters& counters) const {
    LeavingVerdict verdict;
    switch (route(ray, t, verdict)) {
        case Route::Culled:
            return culled_closest_hit(ray, t, false, counters);
        case Route::AmongGuards:
            return guarded_closest_hit(ray, t, verdict, false, counters);
        case Route::InItemBuffer:  // route() gives it to eye rays only
        case Route::Wrapped:
            break;
    }
    return wrapped_->closest_hit(ray, t, counters);
}

std::optional<Hit> ExitCulling::eye_ray_closest_hit(const Ray& ray, Interval t,
                                                    TraceCounters& counters) const {
    LeavingVerdict verdict;
    ViewPixel pixel;
    switch (route_eye_ray(ray, t, verdict, pixel)) {
        case Route::Culled:
            return culled_closest_hit(ray, t, true, counters);
        case Route::AmongGuards:
            return guarded_closest_hit(ray, t, verdict, true, counters);
        case Route::InItemBuffer:
            return item_closest_hit(ray, t, pixel, counters);
        case Route::Wrapped:
            break;
    }
    return wrapped_->eye_ray_closest_hit(ray, t, counters);
}

std::optional<Hit> ExitCulling::culled_closest_hit(const Ray& ray, Interval t, bool eye_ray,
                                                   TraceCounters& counters) const {
    ++counters.culled_exits;
    if (!check_culled_) {
        return std::nullopt;
    }
    TraceCounters ignored;
    std::optional<Hit> truth = eye_ray ? wrapped_->eye_ray_closest_hit(ray, t, ignored)
                                       : wrapped_->closest_hit(ray, t, ignored);
    record_if_violated(ray, truth.has_value());
    return truth;  // a wrong cull is reported, but the picture stays right
}

std::optional<Hit> ExitCulling::guarded_closest_hit(const Ray& ray, Interval t,
                                                    const LeavingVerdict& verdict, bool eye_ray,
                                                    TraceCounters& counters) const {
    ++counters.guard_answers;
    const std::optional<Hit> found =
        closest_hit_among(*scene_, ray, t, verdict.candidates(), counters);
    return check_culled_ ? checked_answer(ray, t, found, eye_ray) : found;
}

std::optional<Hit> ExitCulling::item_closest_hit(const Ray& ray, Interval t, const ViewPixel& pixel,
                                                 TraceCounters& counters) const {
    ++counters.guard_answers;
    const RaySpace space(ray);
    std::optional<Hit> found;
    if (space.valid()) {  // else no hit, as brute force answers such a ray
        const EyeRayPixel at{pixel.x, pixel.y, length(ray.origin - eye_.view().camera().eye)};
        found = closest_hit_in_buffer(*scene_, *eye_items_, space, t, at, counters);
    }
    return check_culled_ ? checked_answer(ray, t, found, true) : found;
}

std::optional<Hit> ExitCulling::checked_answer(const Ray& ray, Interval t,
                                               const std::optional<Hit>& found,
                                               bool eye_ray) const {
    TraceCounters ignored;
    std::optional<Hit> truth = eye_ray ? wrapped_->eye_ray_closest_hit(ray, t, ignored)
                                       : wrapped_->closest_hit(ray, t, ignored);
    const bool same = truth.has_value() == found.has_value() &&
                      (!truth || (truth->t == found->t && truth->polygon == found->polygon));
    record_if_violated(ray, !same, true);
    return truth;  // a wrong answer is reported, but the picture stays right
}

bool ExitCulling::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    LeavingVerdict verdict;
    switch (route(ray, t, verdict)) {
        case Route::Culled:
            break;
        case Route::AmongGuards:
            return guarded_occluded(ray, t, verdict, counters);
        case Route::InItemBuffer:  // route() gives it to eye rays only
        case Route::Wrapped:
            return wrapped_->occluded(ray, t, counters);
    }
    // Culled: nothing ahead, which -de checks.
    ++counters.culled_exits;
    if (check_culled_) {
        TraceCounters ignored;
        const bool truth = wrapped_->occluded(ray, t, ignored);
        record_if_violated(ray, truth);
        return truth;
    }
    return false;
}

bool ExitCulling::guarded_occluded(const Ray& ray, Interval t, const LeavingVerdict& verdict,
                                   TraceCounters& counters) const {
    ++counters.guard_answers;
    const bool found = any_hit_among(*scene_, ray, t, verdict.candidates(), counters);
    if (!check_culled_) {
        return found;
    }
    TraceCounters ignored;
    const bool truth = wrapped_->occluded(ray, t, ignored);
    record_if_violated(ray, truth != found, true);
    return truth;
}

void ExitCulling::closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                     TraceCounters& counters) const {
    packet_closest_hit(packet, hits, false, counters);
}

void ExitCulling::eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                             TraceCounters& counters) const {
    packet_closest_hit(packet, hits, true, counters);
}

ExitCulling::PacketRoutes ExitCulling::packet_routes(const RayPacket& packet, bool eye_rays) const {
    PacketRoutes routes;
    for (std::uint32_t a = packet.active & kAllLanes; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        const Ray& ray = packet.rays[lane];
        const Interval t = packet.t[lane];
        LeavingVerdict& verdict = routes.verdicts[static_cast<std::size_t>(lane)];
        verdict.kind = LeavingVerdict::Kind::Unknown;
        const Route r =
            eye_rays ? route_eye_ray(ray, t, verdict, routes.pixels[static_cast<std::size_t>(lane)])
                     : route(ray, t, verdict);
        routes.culled |= r == Route::Culled ? 1u << lane : 0u;
        routes.guarded |= r == Route::AmongGuards ? 1u << lane : 0u;
        routes.in_items |= r == Route::InItemBuffer ? 1u << lane : 0u;
    }
    return routes;
}

void ExitCulling::packet_closest_hit(const RayPacket& packet, PacketHits& hits, bool eye_rays,
                                     TraceCounters& counters) const {
    const auto pass_on = [&](const RayPacket& lanes) {
        if (eye_rays) {
            wrapped_->eye_ray_closest_hit_packet(lanes, hits, counters);
        } else {
            wrapped_->closest_hit_packet(lanes, hits, counters);
        }
    };
    const PacketRoutes routes = packet_routes(packet, eye_rays);
    const std::uint32_t passed =
        packet.active & kAllLanes & ~(routes.culled | routes.guarded | routes.in_items);
    if (passed == (packet.active & kAllLanes)) {
        pass_on(packet);
        return;
    }
    if (passed != 0) {
        RayPacket rest = packet;
        rest.active = passed;
        pass_on(rest);
    }
    for (std::uint32_t a = routes.culled; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        hits[lane] = culled_closest_hit(packet.rays[lane], packet.t[lane], eye_rays, counters);
    }
    for (std::uint32_t a = routes.guarded; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        hits[lane] = guarded_closest_hit(packet.rays[lane], packet.t[lane],
                                         routes.verdicts[static_cast<std::size_t>(lane)], eye_rays,
                                         counters);
    }
    for (std::uint32_t a = routes.in_items; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        hits[lane] = item_closest_hit(packet.rays[lane], packet.t[lane],
                                      routes.pixels[static_cast<std::size_t>(lane)], counters);
    }
}

std::uint32_t ExitCulling::occluded_packet(const RayPacket& packet, TraceCounters& counters) const {
    const PacketRoutes routes = packet_routes(packet, false);
    const std::uint32_t passed =
        packet.active & kAllLanes & ~(routes.culled | routes.guarded | routes.in_items);
    if (passed == (packet.active & kAllLanes)) {
        return wrapped_->occluded_packet(packet, counters);
    }
    std::uint32_t blocked = 0;
    if (passed != 0) {
        RayPacket rest = packet;
        rest.active = passed;
        blocked = wrapped_->occluded_packet(rest, counters);
    }
    counters.culled_exits += static_cast<std::uint64_t>(std::popcount(routes.culled));
    for (std::uint32_t a = routes.culled; check_culled_ && a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        TraceCounters ignored;
        const bool truth = wrapped_->occluded(packet.rays[lane], packet.t[lane], ignored);
        record_if_violated(packet.rays[lane], truth);
        blocked |= truth ? 1u << lane : 0u;
    }
    for (std::uint32_t a = routes.guarded; a != 0; a &= a - 1) {
        const int lane = std::countr_zero(a);
        const bool hit =
            guarded_occluded(packet.rays[lane], packet.t[lane],
                             routes.verdicts[static_cast<std::size_t>(lane)], counters);
        blocked |= hit ? 1u << lane : 0u;
    }
    return blocked;
}

void ExitCulling::record_if_violated(const Ray& ray, bool violated, bool guarded) const {
    (guarded ? guards_checked_ : checked_).fetch_add(1, std::memory_order_relaxed);
    if (!violated) {
        return;
    }
    (guarded ? guard_violations_ : violations_).fetch_add(1, std::memory_order_relaxed);
    const std::lock_guard lock(violations_mutex_);
    if (first_violations_.size() < kViolationsKept) {
        first_violations_.push_back(ray);
    }
}

std::size_t ExitCulling::memory_bytes() const {
    return table_.memory_bytes() + leaving_.memory_bytes() + eye_.memory_bytes() +
           (eye_items_ ? eye_items_->memory_bytes() : 0) + wrapped_->memory_bytes();
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
    s.eye_coverage = eye_.active();
    s.eye_inactive_reason = eye_.inactive_reason();
    s.pixels = eye_.pixels();
    s.covered_pixels = eye_.covered_pixels();
    s.eye_memory_bytes = eye_.memory_bytes();
    if (eye_items_) {
        s.eye_item_entries = eye_items_->entries();
        s.eye_item_longest = eye_items_->longest_list();
        s.eye_item_memory_bytes = eye_items_->memory_bytes();
    }
    s.leaving_polygons = leaving_.polygons();
    s.leaving_bins_per_side = leaving_.bins_per_side();
    s.leaving_patches_per_side = leaving_.patches_per_side();
    s.leaving_guards = leaving_.guards();
    s.scene_polygons = scene_polygons_;
    s.leaving_empty_fraction = leaving_.empty_fraction();
    s.leaving_memory_bytes = leaving_.memory_bytes();
    s.checking = check_culled_;
    s.checked = checked_.load();
    s.violations = violations_.load();
    s.guards_checked = guards_checked_.load();
    s.guard_violations = guard_violations_.load();
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
    if (s.eye_coverage) {
        const double share =
            s.pixels > 0 ? static_cast<double>(s.covered_pixels) / static_cast<double>(s.pixels)
                         : 0.0;
        std::string line =
            fmt::format("exit culling of eye rays: {} of {} pixels covered ({:.1f}%), {} bytes",
                        s.covered_pixels, s.pixels, 100.0 * share, s.eye_memory_bytes);
        if (s.eye_item_memory_bytes > 0) {
            line += fmt::format(
                "; item buffer of {}x{}-pixel tiles: {} entries (at most {} in a tile), {} bytes",
                kEyeTileSide, kEyeTileSide, s.eye_item_entries, s.eye_item_longest,
                s.eye_item_memory_bytes);
        }
        lines.push_back(std::move(line));
    } else if (!s.eye_inactive_reason.empty()) {
        lines.push_back("exit culling of eye rays by the table: " + s.eye_inactive_reason);
    }
    if (s.leaving_polygons > 0) {
        lines.push_back(fmt::format(
            "exit culling of rays leaving a polygon: {} polygons x {}x{} patches x 6x{}x{} "
            "direction bins, {} guards, {:.1f}% of bins clear but for guards, {} bytes",
            s.leaving_polygons, s.leaving_patches_per_side, s.leaving_patches_per_side,
            s.leaving_bins_per_side, s.leaving_bins_per_side, s.leaving_guards,
            100.0 * s.leaving_empty_fraction, s.leaving_memory_bytes));
    } else if (s.scene_polygons > kMostLeavingTablePolygons) {
        lines.push_back(
            fmt::format("exit culling of rays leaving a polygon: off (more than {} polygons)",
                        kMostLeavingTablePolygons));
    }
    if (s.checking) {
        lines.push_back(
            fmt::format("exit culling check (-de): {} culled rays re-traced, {} hit something; {} "
                        "rays answered from a few polygons (guards, tiles) re-traced, {} answered "
                        "otherwise",
                        s.checked, s.violations, s.guards_checked, s.guard_violations));
        for (const Ray& r : s.first_violations) {
            lines.push_back(fmt::format(
                "  wrongly culled or answered: origin ({:.17g}, {:.17g}, {:.17g}) direction "
                "({:.17g}, {:.17g}, {:.17g})",
                r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z));
        }
    }
    return lines;
}

}  // namespace rt
