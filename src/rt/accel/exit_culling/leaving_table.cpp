// Why "nothing ahead" is safe for a ray leaving polygon P, from origin o with direction d, at
// t > t.min >= 0. Every method skips P itself (the ray names it in Ray::leaves). A polygon of P's
// plane group is missed when plane_group_certainly_missed says so, which the query asks. For any
// other polygon Q the ray hits, polygon_reach's argument (hit_regions/polygon_reach.cpp) gives
// the reported point Y = o + t_Y d and X = o + t_X d, where the line crosses Q's hull (grown by
// Q's rounding r), with Y in Q's reach.
// - Q not in a guard: its directions are in the bins of the patch of P's start box o lies in
//   (the query checks that o lies in the start box, and patch_of() finds a patch whose grown box
//   holds it). For Y in Q's plain box, d points from the patch to Y; for Y in the grazing box,
//   either X lies ahead of o (then d points to X, in the plain box) or o lies between X and Y,
//   in the grazing box too, and the bins hold the grazing box's directions seen edge-on from
//   that part of the patch (as the cell table does, exit_culling_table.cpp).
// - Q in a guard whose own bins, from that patch, do not hold the ray's: as above.
// - Q a guard ruled out by plane_certainly_missed (the exact test's own first step), or in a
//   guarding plane group ruled out by plane_group_certainly_missed.
// - Q in a guard whose box the ray's line misses: the line meets Q's hull grown by r, and the box
//   holds Q's corners grown by twice that (polygon_boxes.h argues the same for the voxel
//   methods' boxes).
// - Q a guard ruled out from P's plane: on the side s of P's plane the ray goes to (n P's unit
//   normal), every corner of Q lies at most H (Guard::height, which adds r) up that side, so X
//   does, and the ray rises at a = s dot(n, d) > 0 from height h = s dot(n, o - c0) (both
//   checked with their rounding), so t_X <= tau = (H - h) / a. Let g(t) be the ray's signed
//   distance from Q's plane, which X is within Q's rho (which holds r) of.
//   - Plane branch: Y lies on Q's plane within r, at t_Y > 0. If t_X >= 0, |g(0)| <= rho +
//     t_X |g'| <= rho + tau |d|; if t_X < 0 < t_Y, g(0) lies between g(t_X) and g(t_Y), so
//     |g(0)| <= rho.
//   - Grazing branch: |g'| <= Q's grazing cosine times |d|, and |t_X| |d| <= L, the largest
//     distance from P's start box to Q's corners: |g(0)| <= rho + grazing cosine * L.
//   Guard::clearance is rho + grazing cosine * L; the query asks that the origin be farther than
//   it plus max(tau, 0) |d| from Q's plane, so Q is hit by neither branch.
// So a ray the query culls hits nothing.
#include "rt/accel/exit_culling/leaving_table.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numeric>
#include <optional>
#include <tuple>
#include <unordered_map>

#include "rt/accel/exit_culling/plane_group_grid.h"
#include "rt/accel/hit_regions/polygon_reach.h"
#include "rt/accel/parallel_parts.h"
#include "rt/accel/voxel/polygon_boxes.h"
#include "rt/geometry/ray_polygon.h"

namespace rt {

namespace {

// Relative headroom on every bound, for the rounding of computing the bounds themselves.
constexpr double kSlack = 1.0 + 1e-9;
// The rounding of a dot product or a difference of doubles, relative to the largest |component|
// concerned: a few ulps, generously.
constexpr double kDotRounding = 1e-14;
constexpr std::uint32_t kNoGroup = 0xffffffffu;
// Scenes of this many polygons build the table on every core unless told otherwise.
constexpr std::size_t kThreadedBuildPolygons = 128;

double largest_coordinate(const Vec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// A polygon joins a plane group only with a usable normal and finite corner 0.
bool may_group(const Scene& scene, const Polygon& p) {
    return p.corner_count >= 3 && is_finite(p.normal) &&
           (p.normal.x != 0.0 || p.normal.y != 0.0 || p.normal.z != 0.0) &&
           is_finite(scene.corner_position(p, 0));
}

// How far up side `sign` of P's plane Q's corners reach, with Q's rounding.
double height_of(const Scene& scene, const PolygonPlane& p, const PolygonPlane& q,
                 std::uint32_t q_id, double sign) {
    const Polygon& polygon = scene.polygons[q_id];
    double height = -Box3::kInfinity;
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
        const Vec3 c = scene.corner_position(polygon, k);
        height = std::max(height, sign * dot(p.normal, c - p.point));
    }
    const double rounding =
        kDotRounding * (q.corners.magnitude() + largest_coordinate(p.point)) + q.rounding;
    return height + rounding * kSlack;
}

// How many bins a set of rows holds, eight bytes at a time.
std::size_t set_bins(std::span<const std::uint16_t> rows) {
    std::size_t count = 0;
    std::size_t i = 0;
    for (; i + 4 <= rows.size(); i += 4) {
        std::uint64_t chunk = 0;
        std::memcpy(&chunk, rows.data() + i, sizeof(chunk));
        count += static_cast<std::size_t>(std::popcount(chunk));
    }
    for (; i < rows.size(); ++i) {
        count += static_cast<std::size_t>(std::popcount(rows[i]));
    }
    return count;
}

// A box as floats rounded outward: lo, then hi.
std::array<float, 6> outward(const Box3& box) {
    return {std::nextafter(static_cast<float>(box.lo.x), -HUGE_VALF),
            std::nextafter(static_cast<float>(box.lo.y), -HUGE_VALF),
            std::nextafter(static_cast<float>(box.lo.z), -HUGE_VALF),
            std::nextafter(static_cast<float>(box.hi.x), HUGE_VALF),
            std::nextafter(static_cast<float>(box.hi.y), HUGE_VALF),
            std::nextafter(static_cast<float>(box.hi.z), HUGE_VALF)};
}

}  // namespace

// What the build knows of the whole scene, and how it makes one polygon's entry.
class LeavingTable::Builder {
public:
    Builder(LeavingTable& table, const Scene& scene, const CullingFrame& frame)
        : table_(table), scene_(scene), count_(scene.polygons.size()) {
        // Every polygon asks for every other's reach and plane: made once.
        reaches_.resize(count_);
        planes_.resize(count_);
        for (std::size_t id = 0; id < count_; ++id) {
            const auto q = static_cast<std::uint32_t>(id);
            reaches_[id] = polygon_reach(scene, q, 0.0, frame.rounding);
            planes_[id] = polygon_plane(scene, q, frame.rounding);
        }
        find_groups();
        grid_groups();
        const auto row_count = static_cast<std::size_t>(table.bins_.rows());
        bands_.assign(count_ * row_count, 0);
        for (std::size_t id = 0; id < count_; ++id) {
            if (!reaches_[id].grazing_box.empty()) {
                table.bins_.band_of(
                    reaches_[id].normal, reaches_[id].grazing_cosine,
                    std::span<std::uint16_t>(bands_).subspan(id * row_count, row_count));
            }
        }
        widen_ = 1e-12 * std::max(frame.positions.magnitude(), 1.0);
        guard_height_ = 1e-8 * length(frame.positions.extent());
        guards_.resize(count_);
        guard_boxes_.resize(count_);
    }

    /// Whether every polygon's corners are finite and its reach (both boxes) too. A NaN corner
    /// is left out of the boxes, yet the exact test may report the polygon hit.
    bool finite() const {
        for (const Polygon& p : scene_.polygons) {
            for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                if (!is_finite(scene_.corner_position(p, k))) {
                    return false;
                }
            }
        }
        return std::all_of(reaches_.begin(), reaches_.end(), [](const PolygonReach& r) {
            return is_finite(r.box.lo) && is_finite(r.box.hi) &&
                   (r.grazing_box.empty() ||
                    (is_finite(r.grazing_box.lo) && is_finite(r.grazing_box.hi)));
        });
    }
    /// Fills polygon p's entry, its masks, and its guards (kept here until gather()).
    void build(std::uint32_t p);
    /// Moves the guards into the table, in polygon order.
    void gather();

private:
    // A unit of the directions from P: one polygon, or a plane group of several.
    struct Unit {
        std::uint32_t key = 0;  ///< the polygon, or the group's leader
        bool touching = false;
        bool emits = false;
        std::size_t bins = 0;  ///< set over every patch
        std::vector<std::uint16_t> rows;
    };

    void find_groups();
    /// The grid of each plane group, in the table (plane_group_grid.h).
    void grid_groups();
    /// Fills p's entry but for its guards; returns its patches.
    std::vector<Box3> set_up(std::uint32_t p);
    /// Every other polygon's directions from p's patches, by unit.
    std::vector<Unit> units_seen_from(std::uint32_t p, const std::vector<Box3>& patches) const;
    /// Chooses p's guards among the units and writes its masks.
    void place(std::uint32_t p, const std::vector<Unit>& units);
    /// Adds polygon q's directions from each patch to `rows` (patch by patch).
    void add_directions(std::uint32_t q, const std::vector<Box3>& patches,
                        std::vector<std::uint16_t>& rows) const;
    /// The guard, and its box in `box`.
    Guard make_guard(std::uint32_t p, const Unit& unit, std::array<float, 6>& box) const;

    LeavingTable& table_;
    const Scene& scene_;
    std::size_t count_;
    std::vector<PolygonReach> reaches_;
    std::vector<PolygonPlane> planes_;
    /// Per polygon, the directions that see it edge-on (DirectionBins::band_of), for its
    /// grazing hits.
    std::vector<std::uint16_t> bands_;
    std::vector<std::uint32_t> leader_;  ///< per polygon: its group's leader, or kNoGroup
    std::vector<std::vector<std::uint32_t>> members_;  ///< per leader: the group, leader first
    std::vector<double> group_scale_;  ///< per leader: its members' corners 0's largest |c|
    std::vector<std::uint32_t> grid_of_leader_;  ///< per leader: its group's grid
    double widen_ = 0.0;
    /// A guard whose corners reach no higher than this up a side of P's plane may be ruled out
    /// from it; higher, the rise would have to be too steep to pay.
    double guard_height_ = 0.0;
    std::vector<std::vector<Guard>> guards_;
    std::vector<std::vector<std::array<float, 6>>> guard_boxes_;  ///< each guard's box
};

// Plane groups: each polygon joins the first earlier leader of its plane (the same normal bit for
// bit, in_plane_group), or leads a group of its own; groups of one are none.
void LeavingTable::Builder::find_groups() {
    leader_.assign(count_, kNoGroup);
    members_.resize(count_);
    group_scale_.assign(count_, 0.0);
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> leaders;
    for (std::uint32_t id = 0; id < count_; ++id) {
        const Polygon& p = scene_.polygons[id];
        if (!may_group(scene_, p)) {
            continue;
        }
        std::vector<std::uint32_t>& same_key = leaders[normal_bits_hash(p.normal)];
        const Vec3 first = scene_.corner_position(p, 0);
        std::uint32_t leader = id;
        for (const std::uint32_t l : same_key) {
            const Polygon& candidate = scene_.polygons[l];
            if (same_normal_bits(candidate.normal, p.normal) &&
                in_plane_group(candidate.normal, scene_.corner_position(candidate, 0), first)) {
                leader = l;
                break;
            }
        }
        if (leader == id) {
            same_key.push_back(id);
        }
        leader_[id] = leader;
        members_[leader].push_back(id);
        group_scale_[leader] = std::max(group_scale_[leader], largest_coordinate(first));
    }
    for (std::uint32_t id = 0; id < count_; ++id) {
        if (leader_[id] != kNoGroup && members_[leader_[id]].size() < 2) {
            leader_[id] = kNoGroup;
        }
    }
}

void LeavingTable::Builder::grid_groups() {
    grid_of_leader_.assign(count_, PlaneGroupGrids::kNoGrid);
    std::vector<Box3> boxes(count_);
    for (std::size_t id = 0; id < count_; ++id) {
        boxes[id] = reaches_[id].box;
    }
    for (std::uint32_t id = 0; id < count_; ++id) {
        if (leader_[id] == id) {
            grid_of_leader_[id] =
                table_.group_grids_.add(scene_.polygons[id].normal, members_[id], boxes);
        }
    }
}

void LeavingTable::Builder::add_directions(std::uint32_t q, const std::vector<Box3>& patches,
                                           std::vector<std::uint16_t>& rows) const {
    const auto& bins = table_.bins_;
    const PolygonReach& reach = reaches_[q];
    const std::size_t row_count = static_cast<std::size_t>(bins.rows());
    for (std::size_t patch = 0; patch < patches.size(); ++patch) {
        const Box3& from = patches[patch];
        const auto set = std::span<std::uint16_t>(rows).subspan(patch * row_count, row_count);
        bins.add_directions_of(box_of_differences(reach.box, from, widen_), set);
        const Box3 common = intersection(from, reach.grazing_box);
        if (!reach.grazing_box.empty() && !common.empty() &&
            grazing_slab_meets_box(reach, common)) {
            const auto band =
                std::span<const std::uint16_t>(bands_).subspan(q * row_count, row_count);
            bins.add_directions_of(box_of_differences(reach.grazing_box, common, widen_), set,
                                   band);
        }
    }
}

LeavingTable::Guard LeavingTable::Builder::make_guard(std::uint32_t p, const Unit& unit,
                                                      std::array<float, 6>& guard_box) const {
    Guard g;
    g.polygon = unit.key;
    g.scene_normal = scene_.polygons[unit.key].normal;
    g.first = scene_.corner_position(scene_.polygons[unit.key], 0);
    const bool group = leader_[unit.key] == unit.key;
    Box3 box;
    for (const std::uint32_t q : group ? std::span<const std::uint32_t>(members_[unit.key])
                                       : std::span<const std::uint32_t>(&unit.key, 1)) {
        box.add(planes_[q].corners.grown(2.0 * planes_[q].rounding * kSlack));
    }
    guard_box = outward(box);
    g.height = {Box3::kInfinity, Box3::kInfinity};
    if (group) {
        g.group_scale = group_scale_[unit.key];
        g.grid = grid_of_leader_[unit.key];
        return g;
    }
    const PolygonPlane& plane = planes_[p];
    const PolygonPlane& other = planes_[unit.key];
    if (!plane.usable || !other.usable) {
        return g;
    }
    Box3 both = table_.polygons_[p].start;
    both.add(other.corners.grown(other.rounding));
    g.normal = other.normal;
    g.offset = dot(other.normal, other.point);
    g.clearance = (other.rho + other.grazing_cosine * length(both.extent())) * kSlack;
    constexpr std::array<double, 2> kSign{1.0, -1.0};
    for (std::size_t side = 0; side < 2; ++side) {
        const double height = height_of(scene_, plane, other, unit.key, kSign[side]);
        if (height <= guard_height_) {
            g.height[side] = height;
        }
    }
    return g;
}

void LeavingTable::Builder::build(std::uint32_t p) {
    const std::vector<Box3> patches = set_up(p);
    std::vector<Unit> units = units_seen_from(p, patches);
    place(p, units);
}

std::vector<Box3> LeavingTable::Builder::set_up(std::uint32_t p) {
    LeavingTable& t = table_;
    Leaving& leaving = t.polygons_[p];
    leaving.start = reaches_[p].box;
    const Vec3 extent = leaving.start.extent();
    // The two longest axes, the longer first.
    const int shortest = extent.x <= extent.y && extent.x <= extent.z ? 0
                         : extent.y <= extent.z                       ? 1
                                                                      : 2;
    leaving.axis = {(shortest + 1) % 3, (shortest + 2) % 3};
    if (extent[leaving.axis[1]] > extent[leaving.axis[0]]) {
        std::swap(leaving.axis[0], leaving.axis[1]);
    }
    for (std::size_t k = 0; k < 2; ++k) {
        const double length_k = extent[leaving.axis[k]];
        leaving.per_length[k] = length_k > 0.0 ? t.patch_side_ / length_k : 0.0;
    }
    const PolygonPlane& plane = planes_[p];
    leaving.normal = plane.usable ? plane.normal : Vec3{};
    leaving.point = plane.point;
    if (leader_[p] != kNoGroup) {
        leaving.group_leader = leader_[p];
        leaving.group_normal = scene_.polygons[leader_[p]].normal;
        leaving.group_point = scene_.corner_position(scene_.polygons[leader_[p]], 0);
        leaving.group_scale = group_scale_[leader_[p]];
        leaving.group_grid = grid_of_leader_[leader_[p]];
    }
    // Each patch grown by a millionth of its size: patch_of() rounds within a few ulps.
    std::vector<Box3> patches(t.patches());
    const auto side = static_cast<std::size_t>(t.patch_side_);
    for (std::size_t patch = 0; patch < patches.size(); ++patch) {
        Box3 box = leaving.start;
        const std::array<std::size_t, 2> index{patch / side, patch % side};
        for (std::size_t k = 0; k < 2; ++k) {
            const int a = leaving.axis[k];
            const double size = extent[a] / t.patch_side_;
            const double lo = leaving.start.lo[a] + static_cast<double>(index[k]) * size;
            box.lo[a] = std::max(leaving.start.lo[a], lo - 1e-6 * size);
            box.hi[a] = index[k] + 1 == side
                            ? leaving.start.hi[a]
                            : std::min(leaving.start.hi[a], lo + size * (1 + 1e-6));
        }
        patches[patch] = box;
    }
    return patches;
}

std::vector<LeavingTable::Builder::Unit> LeavingTable::Builder::units_seen_from(
    std::uint32_t p, const std::vector<Box3>& patches) const {
    const Leaving& leaving = table_.polygons_[p];
    const std::size_t patch_rows = patches.size() * static_cast<std::size_t>(table_.bins_.rows());
    const std::uint32_t own_group = leader_[p];
    std::vector<Unit> units;
    std::vector<std::size_t> unit_of(count_, ~std::size_t{0});
    for (std::uint32_t q = 0; q < count_; ++q) {
        if (q == p || (own_group != kNoGroup && leader_[q] == own_group)) {
            continue;
        }
        const std::uint32_t key = leader_[q] != kNoGroup ? leader_[q] : q;
        if (unit_of[key] == ~std::size_t{0}) {
            unit_of[key] = units.size();
            units.push_back({key, false, false, 0, std::vector<std::uint16_t>(patch_rows, 0)});
        }
        Unit& unit = units[unit_of[key]];
        unit.touching = unit.touching || !intersection(leaving.start, reaches_[q].box).empty();
        unit.emits = unit.emits || scene_.attribute_of(scene_.polygons[q]).emission > 0.0;
        add_directions(q, patches, unit.rows);
    }
    for (Unit& unit : units) {
        unit.bins = set_bins(unit.rows);
    }
    return units;
}

// Guards first: the units that touch P, then lights, then by the directions they cover (a single
// polygon needs a usable normal to be told apart by its plane). Each guard's bins go into the
// masks as its bit, the others' together as kOthers.
void LeavingTable::Builder::place(std::uint32_t p, const std::vector<Unit>& units) {
    LeavingTable& t = table_;
    std::vector<std::size_t> order(units.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto rank = [&](const Unit& u) {
        return std::make_tuple(u.touching, u.emits, u.bins, -static_cast<double>(u.key));
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return rank(units[a]) > rank(units[b]); });
    // Rows are per patch and face row; a row's bit k is column k.
    const std::size_t patch_rows = t.patches() * static_cast<std::size_t>(t.bins_.rows());
    const auto side_bins = static_cast<std::size_t>(t.bins_.side());
    const auto masks =
        std::span<GuardMask>(t.masks_).subspan(p * patch_rows * side_bins, patch_rows * side_bins);
    const auto scatter = [&](std::span<const std::uint16_t> rows, GuardMask bit) {
        for (std::size_t row = 0; row < patch_rows; ++row) {
            for (std::uint32_t columns = rows[row]; columns != 0; columns &= columns - 1) {
                masks[row * side_bins + static_cast<std::size_t>(std::countr_zero(columns))] |= bit;
            }
        }
    };
    std::vector<std::uint16_t> others(patch_rows, 0);
    for (const std::size_t u : order) {
        const Unit& unit = units[u];
        const bool group = leader_[unit.key] == unit.key;
        if (unit.bins > 0 && guards_[p].size() < kMostGuards &&
            (group || planes_[unit.key].usable)) {
            scatter(unit.rows, GuardMask{1} << guards_[p].size());
            guards_[p].push_back(make_guard(p, unit, guard_boxes_[p].emplace_back()));
            continue;
        }
        for (std::size_t row = 0; row < patch_rows; ++row) {
            others[row] |= unit.rows[row];
        }
    }
    scatter(others, kOthers);
}

void LeavingTable::Builder::gather() {
    for (std::size_t p = 0; p < count_; ++p) {
        table_.polygons_[p].first_guard = static_cast<std::uint32_t>(table_.guards_.size());
        table_.polygons_[p].guards = static_cast<std::uint32_t>(guards_[p].size());
        table_.guards_.insert(table_.guards_.end(), guards_[p].begin(), guards_[p].end());
        table_.polygons_[p].first_box_block = table_.guard_boxes_.add(guard_boxes_[p]);
    }
}

LeavingTable::LeavingTable(const Scene& scene, const CullingFrame& frame, int threads,
                           int bins_per_side)
    : bins_(bins_per_side) {
    const std::size_t count = scene.polygons.size();
    if (count == 0 || count > kMostLeavingTablePolygons) {
        return;
    }
    patch_side_ = count <= kFinePatchPolygons ? kMostPatchesPerSide : 1;
    polygons_.resize(count);
    masks_.assign(count * patches() * 6 * static_cast<std::size_t>(bins_.side() * bins_.side()), 0);
    Builder builder(*this, scene, frame);
    if (!builder.finite()) {
        // A corner or a reach beyond the doubles' range has no directions to bin: no table.
        polygons_.clear();
        masks_.clear();
        group_grids_ = {};
        return;
    }
    // Each polygon writes only its own slots. Its work grows as the square of the polygons:
    // every core from kThreadedBuildPolygons on.
    const int parts =
        threads > 0 ? std::min(threads, 64) : (count >= kThreadedBuildPolygons ? every_core() : 1);
    share_out(count, parts,
              [&](std::size_t id, int) { builder.build(static_cast<std::uint32_t>(id)); });
    builder.gather();
    narrow_masks_if_they_fit();
}

void LeavingTable::narrow_masks_if_they_fit() {
    constexpr std::size_t kNarrowGuards = 15;
    if (std::any_of(polygons_.begin(), polygons_.end(),
                    [](const Leaving& p) { return p.guards > kNarrowGuards; })) {
        return;
    }
    constexpr GuardMask kNarrowOthers = GuardMask{1} << kNarrowGuards;
    narrow_masks_.resize(masks_.size());
    std::transform(masks_.begin(), masks_.end(), narrow_masks_.begin(), [](GuardMask m) {
        return static_cast<std::uint16_t>((m & (kNarrowOthers - 1)) |
                                          ((m & kOthers) != 0 ? kNarrowOthers : 0));
    });
    std::vector<GuardMask>().swap(masks_);  // its memory too
    others_bit_ = kNarrowOthers;
}

void LeavingTable::verdict(const Ray& ray, Interval t, LeavingVerdict& verdict) const {
    verdict.kind = LeavingVerdict::Kind::Unknown;
    verdict.count = 0;
    const std::uint32_t id = ray.leaves;
    if (id >= polygons_.size() || !(t.min >= 0.0)) {
        return;
    }
    const Leaving& p = polygons_[id];
    if (!p.start.contains(ray.origin)) {
        return;
    }
    const Vec3& d = ray.direction;
    if (!is_finite(d) || (d.x == 0.0 && d.y == 0.0 && d.z == 0.0)) {
        return;
    }
    // The line's reciprocals serve the direction's bin and every guard's box.
    const LineProbe line(ray);
    const GuardMask may_meet = mask(id, patch_of(p, ray.origin), bins_.bin_of(d, line.inverse));
    if ((may_meet & others_bit_) != 0) {
        return;
    }
    // Each guard the ray's bin may meet is missed, or kept as a candidate: a single polygon
    // itself, a plane group by those of its polygons near where the ray crosses their plane.
    // Their boxes first, all at once (guard_boxes.h).
    for (std::uint32_t bits = guard_boxes_.met(line, p.first_box_block, may_meet); bits != 0;
         bits &= bits - 1) {
        const Guard& g =
            guards_[p.first_guard + static_cast<std::uint32_t>(std::countr_zero(bits))];
        if (misses_guard(ray, t, p, g)) {
            continue;
        }
        if (g.group_scale >= 0.0) {
            // The group's polygons near where the ray crosses their plane.
            if (!group_grids_.add_candidates(g.grid, ray, g.first, g.group_scale, verdict.polygons,
                                             verdict.count)) {
                verdict.count = 0;
                return;  // unsure
            }
            continue;
        }
        if (verdict.count == verdict.polygons.size()) {
            verdict.count = 0;
            return;  // unsure
        }
        verdict.polygons[verdict.count++] = g.polygon;
    }
    if (p.group_scale >= 0.0) {
        const Vec3& leader = p.group_point;
        if (!plane_group_certainly_missed(ray, p.group_normal, leader, p.group_scale, t.min) &&
            !group_grids_.add_candidates(p.group_grid, ray, leader, p.group_scale, verdict.polygons,
                                         verdict.count)) {
            verdict.count = 0;
            return;  // unsure
        }
    }
    verdict.kind =
        verdict.count == 0 ? LeavingVerdict::Kind::NothingAhead : LeavingVerdict::Kind::AmongGuards;
}

bool LeavingTable::misses_guard(const Ray& ray, Interval t, const Leaving& p,
                                const Guard& g) const {
    if (g.group_scale >= 0.0) {
        return plane_group_certainly_missed(ray, g.scene_normal, g.first, g.group_scale, t.min);
    }
    if (plane_certainly_missed(ray, g.scene_normal, g.first, t)) {
        return true;
    }
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    const double toward = dot(p.normal, d);
    const std::size_t side = toward < 0.0 ? 1 : 0;
    if (!(g.height[side] < Box3::kInfinity)) {
        return false;
    }
    const double sign = side == 0 ? 1.0 : -1.0;
    const double o_size = largest_coordinate(o);
    const double d_size = largest_coordinate(d);
    // Lower bounds on the rise a and the origin's height h; tau |d| <= (H - h) |d|_1 / a.
    const double rise = sign * toward - kDotRounding * d_size;
    if (!(rise > 0.0)) {
        return false;
    }
    const double height =
        sign * dot(p.normal, o - p.point) - kDotRounding * (o_size + largest_coordinate(p.point));
    const double d_sum = std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    const double above = g.height[side] - height;
    const double climb = above > 0.0 ? above * (d_sum / rise) * kSlack : 0.0;
    const double distance =
        std::fabs(dot(g.normal, o) - g.offset) - kDotRounding * (o_size + std::fabs(g.offset));
    return std::isfinite(climb) && distance > (g.clearance + climb) * kSlack;
}

double LeavingTable::empty_fraction() const {
    const auto share = [this](const auto& masks) {
        if (masks.empty()) {
            return 0.0;
        }
        const auto empty = std::count_if(masks.begin(), masks.end(),
                                         [this](GuardMask m) { return (m & others_bit_) == 0; });
        return static_cast<double>(empty) / static_cast<double>(masks.size());
    };
    return narrow_masks_.empty() ? share(masks_) : share(narrow_masks_);
}

std::size_t LeavingTable::memory_bytes() const {
    return polygons_.capacity() * sizeof(Leaving) + guards_.capacity() * sizeof(Guard) +
           guard_boxes_.memory_bytes() + masks_.capacity() * sizeof(GuardMask) +
           narrow_masks_.capacity() * sizeof(std::uint16_t) + group_grids_.memory_bytes();
}

}  // namespace rt
