// Exit culling for rays that leave a polygon (Ray::leaves): reflected, refracted and diffuse rays,
// rim probes and shadow feelers. The cell table (exit_culling_table.h) passes all of them on, as
// the cell they start in holds the polygon they leave and so has every direction. This table
// asks instead, for each polygon P and each patch of the box its rays start in, in which
// directions a ray leaving P can hit anything:
// - P itself never, as every method skips it for such a ray;
// - the polygons of P's plane group (in_plane_group, geometry/ray_polygon.h) not when the ray
//   passes plane_group_certainly_missed: a checkerboard's other squares;
// - a few "guards" chosen per polygon keep their directions apart, and a ray in one of them is
//   checked against the guard itself: the polygons whose boxes touch P's (which would put every
//   direction in P's set), lights' polygons (which every shadow feeler ends on) and the polygons
//   and plane groups that cover the most directions from P. A guard is missed when its plane is
//   left behind or not reached (the exact test's first step), when the ray's line misses its
//   box, or, for a neighbour behind P's plane, when the ray rises from P far enough from it;
// - every other polygon by its directions.
// A ray leaving a checkerboard's square, or a box's face, into the sky, or towards a light past a
// box, then ends at once, where it used to walk the whole structure. A ray whose directions hold
// only guards, some of which it may meet, is confined to those (a plane group's to its polygons
// near the crossing, plane_group_grid.h): ExitCulling answers it by their exact tests alone.
// Conservative like the cell table, so the picture never changes (leaving_table.cpp argues why);
// -de checks the rays it culls.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rt/accel/exit_culling/direction_bins.h"
#include "rt/accel/exit_culling/guard_boxes.h"
#include "rt/accel/exit_culling/occupied_cells.h"
#include "rt/accel/exit_culling/plane_group_grid.h"
#include "rt/core/bounds.h"
#include "rt/core/ray.h"
#include "rt/scene/scene.h"

namespace rt {

/// Scenes of more polygons get no table: the build looks at every pair of polygons, about a
/// quarter of a microsecond each, and a big mesh's neighbours touch, which fills a polygon's
/// directions anyway. (The gallery, 224 polygons in a closed room, built it in 17 ms on one
/// thread and traced 16 ms faster with it, answers from guards included: no gain.)
inline constexpr std::size_t kMostLeavingTablePolygons = 160;
/// A direction's mask: which guards, and whether any other polygon, may be met there.
using GuardMask = std::uint32_t;
/// Guards per polygon, at most: one bit each in a direction's mask, beside the others' bit.
inline constexpr std::size_t kMostGuards = 31;
/// Polygons a ray may be confined to, at most: more, and the table says it cannot tell.
inline constexpr std::size_t kMostLeavingCandidates = 16;
/// A polygon's start box is cut into this many patches a side (along its two longest axes), each
/// with its own directions, in scenes of up to kFinePatchPolygons polygons; else not cut. From a
/// patch, a nearby polygon covers fewer directions.
inline constexpr int kMostPatchesPerSide = 2;
inline constexpr std::size_t kFinePatchPolygons = 128;
/// Direction bins along each edge of a face of the direction cube: finer than the cell table's,
/// as a light seen past a box's edge is the usual case here.
inline constexpr int kLeavingBinsPerSide = 16;

/// What the table says of a ray leaving a polygon (LeavingTable::verdict). `polygons` is left
/// unset past `count`: a verdict is made for every ray leaving a polygon.
struct LeavingVerdict {  // NOLINT(cppcoreguidelines-pro-type-member-init)
    enum class Kind : std::uint8_t {
        Unknown,       ///< the table cannot tell: the method must walk the ray
        NothingAhead,  ///< the ray hits no polygon at any t > t.min
        /// Any hit it has is on one of `polygons`: single polygons that guard the one it leaves,
        /// and the polygons of guarding plane groups near where it crosses their plane.
        AmongGuards,
    };
    Kind kind = Kind::Unknown;
    std::uint32_t count = 0;  ///< of `polygons`, for AmongGuards
    std::array<std::uint32_t, kMostLeavingCandidates> polygons;

    std::span<const std::uint32_t> candidates() const { return {polygons.data(), count}; }
};

class LeavingTable {
public:
    /// No table: nothing_ahead() is always false.
    LeavingTable() = default;
    /// The table for `scene` (it keeps what it needs of it), with `frame`'s rounding allowances;
    /// none for a scene of more than kMostLeavingTablePolygons polygons. `threads` build it (the
    /// same table for any number).
    LeavingTable(const Scene& scene, const CullingFrame& frame, int threads,
                 int bins_per_side = kLeavingBinsPerSide);

    bool active() const { return !polygons_.empty(); }

    /// Which polygons the ray, leaving polygon ray.leaves, may hit at t > t.min: none, only a few
    /// named ones (guards its own tests could not rule out, and polygons of guarding plane groups
    /// near where it crosses their plane), or it cannot tell. Unknown for a ray that names no
    /// polygon, starts outside the box a hit on its polygon can lie in, has t.min < 0, or a zero or
    /// non-finite direction. Written into `verdict`, which a caller keeps from ray to ray.
    void verdict(const Ray& ray, Interval t, LeavingVerdict& verdict) const;
    /// True only if the ray can hit no polygon at any t > t.min (verdict NothingAhead).
    bool nothing_ahead(const Ray& ray, Interval t) const {
        LeavingVerdict v;
        verdict(ray, t, v);
        return v.kind == LeavingVerdict::Kind::NothingAhead;
    }

    std::size_t polygons() const { return polygons_.size(); }
    int bins_per_side() const { return bins_.side(); }
    int patches_per_side() const { return patch_side_; }
    std::size_t guards() const { return guards_.size(); }
    /// The share of (polygon, patch, bin) entries that say "nothing ahead", guards aside.
    double empty_fraction() const;
    std::size_t memory_bytes() const;

private:
    /// A polygon, or a plane group, kept apart from a polygon's directions (leaving_table.cpp).
    struct Guard {
        std::uint32_t polygon = 0;  ///< the polygon, or the group's leader
        /// Its scene normal and corner 0, as the exact test reads them: kept here, a query reads
        /// them at once instead of through the polygon's record and its corner list.
        Vec3 scene_normal;
        Vec3 first;
        /// For a group, the largest |coordinate| of its corners 0; negative for one polygon.
        /// (Its box, every member's corners grown and rounded outward, is in guard_boxes_.)
        double group_scale = -1.0;
        // Only for one polygon:
        Vec3 normal;             ///< unit
        double offset = 0.0;     ///< dot(normal, its corner 0)
        double clearance = 0.0;  ///< the least distance from its plane, before the ray's own term
        std::uint32_t grid = PlaneGroupGrids::kNoGrid;  ///< for a group, its grid
        /// How far its corners reach up each side of P's plane (the side P's normal points to,
        /// then the other); infinite when it is not ruled out that way.
        std::array<double, 2> height{};
    };
    struct Leaving {
        Box3 start;  ///< a ray must start here to be culled: a hit on P away from edge-on lies here
        /// The start box's two longest axes, and the patches per unit length along each (0 for
        /// an axis of no extent).
        std::array<int, 2> axis{0, 1};
        std::array<double, 2> per_length{};
        Vec3 normal;  ///< unit; zero when P's normal is unusable
        Vec3 point;   ///< corner 0
        /// The leader of P's plane group, and the largest |coordinate| of the group's corners 0;
        /// negative when P is alone in its plane.
        std::uint32_t group_leader = 0;
        Vec3 group_normal;  ///< the leader's scene normal and corner 0, as for a guard
        Vec3 group_point;
        double group_scale = -1.0;
        std::uint32_t group_grid = PlaneGroupGrids::kNoGrid;
        std::uint32_t first_guard = 0;
        std::uint32_t guards = 0;
        std::uint32_t first_box_block = 0;  ///< its guards' boxes in guard_boxes_
    };
    class Builder;

    std::size_t patches() const {
        return static_cast<std::size_t>(patch_side_) * static_cast<std::size_t>(patch_side_);
    }
    /// The patch of `p`'s start box holding `origin` (a point of it). The index along each axis
    /// is a rounded product, a few ulps of the start box's length from the exact one: the
    /// patches are grown by a millionth of their length, so the one it names holds the origin.
    std::size_t patch_of(const Leaving& p, const Vec3& origin) const {
        const double top = patch_side_ - 1;
        const double first = (origin[p.axis[0]] - p.start.lo[p.axis[0]]) * p.per_length[0];
        const double second = (origin[p.axis[1]] - p.start.lo[p.axis[1]]) * p.per_length[1];
        return static_cast<std::size_t>(std::clamp(first, 0.0, top)) *
                   static_cast<std::size_t>(patch_side_) +
               static_cast<std::size_t>(std::clamp(second, 0.0, top));
    }
    /// Which of the polygon's guards (bit g), and whether any other polygon (others_bit_), may
    /// be met in the bin's directions from the patch.
    GuardMask mask(std::uint32_t polygon, std::size_t patch, const DirectionBin& bin) const {
        const auto side = static_cast<std::size_t>(bins_.side());
        const std::size_t at =
            ((polygon * patches() + patch) * 6 + static_cast<std::size_t>(bin.face)) * side * side +
            static_cast<std::size_t>(bin.row) * side + static_cast<std::size_t>(bin.column);
        return narrow_masks_.empty() ? masks_[at] : narrow_masks_[at];
    }
    /// The others' bit while the table is built, in masks_.
    static constexpr GuardMask kOthers = GuardMask{1} << kMostGuards;
    /// Keeps the masks in 16 bits when no polygon has more than 15 guards: half the memory, and
    /// the masks a render reads stay in the cache (twocubes4's take 0.9 MB so).
    void narrow_masks_if_they_fit();
    /// Whether the ray leaving `p` surely misses the guard (its directions aside).
    bool misses_guard(const Ray& ray, Interval t, const Leaving& p, const Guard& g) const;

    DirectionBins bins_{1};
    int patch_side_ = 1;
    std::vector<Leaving> polygons_;
    std::vector<Guard> guards_;
    GuardBoxes guard_boxes_;
    PlaneGroupGrids group_grids_;  ///< per plane group, which of its polygons a crossing is near
    /// Per polygon, patch and bin (face, row, column): mask(). In masks_, or in narrow_masks_
    /// (bit 15 for the others) when they fit.
    std::vector<GuardMask> masks_;
    std::vector<std::uint16_t> narrow_masks_;
    GuardMask others_bit_ = kOthers;
};

}  // namespace rt
