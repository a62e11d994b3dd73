// Exit-ray culling (manual part three; -De disables it, -de debugs it): an Accelerator wrapping
// another. A ray the inclusion-cone table says can hit nothing ends at once, counted in
// TraceCounters::culled_exits. A ray leaving a polygon that the leaving table confines to a few
// polygons is answered by their exact tests alone (guard_hits.h), counted in
// TraceCounters::guard_answers; every other ray goes to the wrapped accelerator. The tables are
// conservative, so the picture never changes; -de re-traces every culled or answered ray to
// prove it. A packet is tested lane by lane against the tables, and its lanes that are neither
// culled nor answered go on as one packet, so that the wrapped method's packet walk (the BVH's)
// still serves them. Eye rays (Accelerator::eye_ray_closest_hit) are culled by the pixels the scene
// covers instead (eye_coverage.h), those that may hit something answered from an item buffer of
// tiles of pixels (zbuffer/item_buffer.h), and only go to the table when they are not eye rays of
// the scene's view.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/accel/exit_culling/exit_culling_table.h"
#include "rt/accel/exit_culling/eye_coverage.h"
#include "rt/accel/exit_culling/leaving_table.h"
#include "rt/accel/zbuffer/item_buffer.h"

namespace rt {

struct ExitCullingSettings {
    int grid_resolution = 0;    ///< cells along each axis (1..64); 0: chosen from the scene
    int bins_per_side = 8;      ///< direction bins along each edge of a cube face (1..16)
    bool check_culled = false;  ///< -de: trace every culled ray with the wrapped accelerator too
    int build_threads = 0;      ///< 0: one a core for a large scene (parallel_parts.h)
    bool eye_coverage = true;   ///< cull eye rays by the pixels the scene covers (eye_coverage.h)
    /// Answer the eye rays the coverage does not cull from an item buffer of tiles of pixels
    /// (zbuffer/item_buffer.h), as the z-buffer answers them from its pixels', with `answers`.
    bool eye_items = true;
    /// Answer rays from a few exact tests (their guards, the eye rays' item buffer) where the
    /// tables allow: brute force's answers. Off where the method is to answer every ray it is
    /// given, as a switch that makes it answer otherwise on purpose, or a debugging layer
    /// watching it, asks (accelerator_stack.cpp). Culling stays: such a method finds nothing on a
    /// ray that meets nothing too.
    bool answers = true;
    /// Cull rays leaving a polygon by the directions that polygon sees (leaving_table.h).
    bool leaving_table = true;
};

/// What -p prints for exit culling. The number of culled rays is TraceCounters::culled_exits.
struct ExitCullingStatistics {
    int grid_resolution = 0;
    int bins_per_side = 0;
    std::size_t regions = 0;         ///< grid cells, each with 6 * bins_per_side^2 bins
    std::size_t occupied_cells = 0;  ///< cells that may hold a hit point
    double empty_fraction = 0.0;     ///< share of (cell, bin) entries saying "nothing ahead"
    std::size_t memory_bytes = 0;    ///< the table alone
    double build_seconds = 0.0;
    bool eye_coverage = false;              ///< whether eye rays are culled by the pixels covered
    std::string eye_inactive_reason;        ///< why not, when not
    std::size_t pixels = 0;                 ///< of the view
    std::size_t covered_pixels = 0;         ///< through which an eye ray may hit something
    std::size_t eye_memory_bytes = 0;       ///< the coverage alone
    std::size_t eye_item_entries = 0;       ///< the eye rays' item buffer: its entries,
    std::size_t eye_item_longest = 0;       ///< the most in a tile,
    std::size_t eye_item_memory_bytes = 0;  ///< and its size; 0: none
    std::size_t leaving_polygons = 0;       ///< polygons with a leaving table; 0: none
    int leaving_bins_per_side = 0;
    int leaving_patches_per_side = 0;
    std::size_t leaving_guards = 0;
    std::size_t scene_polygons = 0;       ///< of the scene, to say why there is none
    double leaving_empty_fraction = 0.0;  ///< share of (polygon, bin) entries saying "nothing"
    std::size_t leaving_memory_bytes = 0;
    bool checking = false;               ///< -de
    std::uint64_t checked = 0;           ///< -de: culled rays re-traced
    std::uint64_t violations = 0;        ///< -de: culled rays that did hit something
    std::uint64_t guards_checked = 0;    ///< -de: rays answered from guards or tiles, re-traced
    std::uint64_t guard_violations = 0;  ///< -de: of those, answered otherwise by the method
    std::vector<Ray> first_violations;   ///< -de: up to 10 of either, to reproduce
};

/// The lines -p (and -de at the end of a run) prints, without trailing newlines.
std::vector<std::string> describe(const ExitCullingStatistics& statistics);

class ExitCulling : public Accelerator {
public:
    /// Builds the table for the scene, which must outlive this, as must `wrapped`'s scene, and
    /// the eye rays' coverage for the scene's view.
    ExitCulling(const Scene& scene, std::unique_ptr<Accelerator> wrapped,
                const ExitCullingSettings& settings = {});

    std::string_view name() const override { return name_; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;
    /// Culled by the coverage when the ray is an eye ray of the scene's view, else as
    /// closest_hit; one not culled goes on as an eye ray.
    std::optional<Hit> eye_ray_closest_hit(const Ray& ray, Interval t,
                                           TraceCounters& counters) const override;
    /// Each lane as closest_hit answers it: the culled lanes here (counted as closest_hit counts
    /// them), the others in one packet to the wrapped accelerator.
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override;
    /// The same, each lane as eye_ray_closest_hit answers it.
    void eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                    TraceCounters& counters) const override;
    /// Each lane as occluded answers it, the lanes not culled in one packet.
    std::uint32_t occluded_packet(const RayPacket& packet, TraceCounters& counters) const override;
    /// False: most rays leaving a polygon (the feelers among them) are answered here from the
    /// table, one by one; asked in packets, cornell's feelers took 21 % more of the render
    /// (docs/lab/feeler-packets-2026-12-06.md).
    bool walks_packets() const override { return false; }
    /// The table, the eye rays' coverage and the wrapped accelerator.
    std::size_t memory_bytes() const override;

    const Accelerator& wrapped() const { return *wrapped_; }
    ExitCullingStatistics statistics() const;

private:
    /// How a ray is answered: ended at once, from its guards' exact tests, from the eye rays'
    /// item buffer, or by the wrapped method's walk.
    enum class Route : std::uint8_t { Culled, AmongGuards, InItemBuffer, Wrapped };
    /// The route the tables give the ray: a ray leaving a polygon is culled, or confined to some
    /// of its guards, by that polygon's directions (the verdict is left in `verdict`); any other,
    /// or one those do not cull, is culled by the cells' directions. The cells' first test
    /// inline: a ray leaving a surface starts in a full cell and is passed on by it alone.
    Route route(const Ray& ray, Interval t, LeavingVerdict& verdict) const {
        if (ray.leaves != kLeavesNoPolygon) {
            leaving_.verdict(ray, t, verdict);
            if (verdict.kind == LeavingVerdict::Kind::NothingAhead) {
                return Route::Culled;
            }
        }
        if (!table_.starts_in_full_cell(ray.origin) && table_.nothing_ahead(ray, t)) {
            return Route::Culled;
        }
        return verdict.kind == LeavingVerdict::Kind::AmongGuards && answers_ ? Route::AmongGuards
                                                                             : Route::Wrapped;
    }
    /// The route of an eye ray: by the coverage when it is an eye ray of the scene's view (its
    /// pixel then in `pixel`), through the item buffer when it may hit something.
    Route route_eye_ray(const Ray& ray, Interval t, LeavingVerdict& verdict,
                        ViewPixel& pixel) const {
        switch (eye_.verdict(ray, t, pixel)) {
            case EyeCoverage::Verdict::MayHit:
                return eye_items_ ? Route::InItemBuffer : Route::Wrapped;
            case EyeCoverage::Verdict::HitsNothing:
                return Route::Culled;
            case EyeCoverage::Verdict::NotAnEyeRay:
                break;
        }
        return route(ray, t, verdict);
    }
    /// The answer for a culled ray: none, or under -de the wrapped accelerator's, checked.
    std::optional<Hit> culled_closest_hit(const Ray& ray, Interval t, bool eye_ray,
                                          TraceCounters& counters) const;
    /// closest_hit for a ray confined to its guards: their exact tests alone, or under -de the
    /// wrapped accelerator's answer, checked against theirs.
    std::optional<Hit> guarded_closest_hit(const Ray& ray, Interval t,
                                           const LeavingVerdict& verdict, bool eye_ray,
                                           TraceCounters& counters) const;
    /// closest_hit for an eye ray through `pixel` from the item buffer's candidates, or under -de
    /// as guarded_closest_hit.
    std::optional<Hit> item_closest_hit(const Ray& ray, Interval t, const ViewPixel& pixel,
                                        TraceCounters& counters) const;
    /// -de: the wrapped accelerator's answer, and whether `found` is the same recorded.
    std::optional<Hit> checked_answer(const Ray& ray, Interval t, const std::optional<Hit>& found,
                                      bool eye_ray) const;
    /// occluded for a ray confined to its guards, as guarded_closest_hit.
    bool guarded_occluded(const Ray& ray, Interval t, const LeavingVerdict& verdict,
                          TraceCounters& counters) const;
    /// The routes of a packet's active lanes: the culled and the guarded lanes as bits, and the
    /// guarded lanes' verdicts.
    struct PacketRoutes {
        std::uint32_t culled = 0;
        std::uint32_t guarded = 0;
        std::uint32_t in_items = 0;
        std::array<LeavingVerdict, kPacketSize> verdicts;
        std::array<ViewPixel, kPacketSize> pixels;  ///< of the lanes in_items
    };
    PacketRoutes packet_routes(const RayPacket& packet, bool eye_rays) const;
    /// closest_hit_packet and eye_ray_closest_hit_packet.
    void packet_closest_hit(const RayPacket& packet, PacketHits& hits, bool eye_rays,
                            TraceCounters& counters) const;
    /// -de: records a culled ray (violated: the wrapped accelerator finds a hit on it), or with
    /// `guarded` a ray answered from its guards (violated: the wrapped accelerator answers
    /// otherwise).
    void record_if_violated(const Ray& ray, bool violated, bool guarded = false) const;

    const Scene* scene_;
    std::unique_ptr<Accelerator> wrapped_;
    double build_seconds_ = 0.0;  ///< set while table_ and eye_ are built: declared before
    ExitCullingTable table_;
    LeavingTable leaving_;
    EyeCoverage eye_;
    std::unique_ptr<ItemBuffer> eye_items_;  ///< null: none
    bool answers_;                           ///< ExitCullingSettings::answers
    bool check_culled_;
    std::size_t scene_polygons_;
    std::string name_;
    mutable std::atomic<std::uint64_t> checked_{0};
    mutable std::atomic<std::uint64_t> violations_{0};
    mutable std::atomic<std::uint64_t> guards_checked_{0};
    mutable std::atomic<std::uint64_t> guard_violations_{0};
    mutable std::mutex violations_mutex_;
    mutable std::vector<Ray> first_violations_;
};

/// The grid resolution used when the settings leave it at 0: about twice the cube root of the
/// polygon count, within 4..8 (build time grows as its sixth power).
int default_exit_culling_resolution(std::size_t polygon_count);

/// The eye rays' item buffer: pixels a side of its tiles, the most polygons a scene may have for
/// one, and the most memory it may take.
inline constexpr int kEyeTileSide = 8;
inline constexpr std::size_t kMostEyeItemPolygons = 8192;
inline constexpr std::size_t kMostEyeItemBytes = std::size_t{16} << 20;

}  // namespace rt
