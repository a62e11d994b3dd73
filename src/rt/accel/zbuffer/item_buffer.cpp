// Why a pixel's list holds every polygon an eye ray through it can report a hit on.
//
// An eye ray's hit point Y lies in the polygon's reach (hit_regions/polygon_reach.h), computed
// for the smallest |cos| a line through the polygon and (within eye_slack) through the eye can
// make with it, and projects into the footprint of any region that holds it
// (hit_regions/eye_view.cpp). The footprint used is that of the reach's part at depth >=
// near_depth: for a reach wholly in front of the near plane, the convex hull of the corners each
// grown by the reach's box growth (tighter than the box); for one crossing it, the reach's box
// cut by the plane. A reach wholly behind is never hit.
//
// Each polygon's `nearest` is the distance from E to its reach's box, <= |Y - E|, and since
// |Y - O| >= |Y - E| - |O - E|, no hit on it is nearer than t = (nearest - |O - E|) / |d|.
#include "rt/accel/zbuffer/item_buffer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "rt/accel/hit_regions/polygon_reach.h"
#include "rt/accel/lane_exact_hit.h"

#include <fmt/format.h>

namespace rt {

ItemBuffer::ItemBuffer(const Scene& scene, const Camera& view, const ZBufferSettings& settings)
    : eye_(view, scene.bounds()),
      max_bytes_(settings.max_bytes),
      tile_side_(std::max(settings.tile_side, 1)) {
    if (!eye_.usable()) {
        active_ = false;
        inactive_reason_ = "the view has no area";
        return;
    }
    const auto side = static_cast<std::size_t>(tile_side_);
    tiles_across_ = (static_cast<std::size_t>(view.width) + side - 1) / side;
    tiles_down_ = (static_cast<std::size_t>(view.height) + side - 1) / side;
    const std::size_t count = scene.polygons.size();
    if (!fits(count, 0)) {
        return;
    }
    std::vector<PixelFootprint> footprints(count);
    std::vector<double> nearest(count);
    std::uint64_t total = 0;
    for (std::uint32_t id = 0; id < count; ++id) {
        footprints[id] = tiles_of(footprint(scene, id, nearest[id]));
        const PixelFootprint& f = footprints[id];
        if (!f.empty()) {
            total += static_cast<std::uint64_t>(f.x1 - f.x0 + 1) * (f.y1 - f.y0 + 1);
            ranked_polygons_.push_back(id);
        }
    }
    if (!fits(count, total)) {
        ranked_polygons_ = {};
        return;
    }
    std::stable_sort(ranked_polygons_.begin(), ranked_polygons_.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return nearest[a] < nearest[b]; });
    for (const std::uint32_t id : ranked_polygons_) {
        ranked_nearest_.push_back(nearest[id]);
    }
    std::vector<PixelFootprint> ranked(ranked_polygons_.size());
    for (std::size_t rank = 0; rank < ranked.size(); ++rank) {
        ranked[rank] = footprints[ranked_polygons_[rank]];
    }
    fill(ranked);
}

PixelFootprint ItemBuffer::tiles_of(const PixelFootprint& f) const {
    if (f.empty()) {
        return f;
    }
    return {f.x0 / tile_side_, f.y0 / tile_side_, f.x1 / tile_side_, f.y1 / tile_side_};
}

bool ItemBuffer::fits(std::size_t polygons, std::uint64_t entries) {
    const std::uint64_t tiles = static_cast<std::uint64_t>(tiles_across_) * tiles_down_;
    // Offsets and their fill cursors, the entries, and per polygon its footprint, depth and rank.
    const double bytes = 8.0 * (static_cast<double>(tiles) + 1.0) +
                         4.0 * static_cast<double>(entries) +
                         static_cast<double>(polygons) * (sizeof(PixelFootprint) + 8.0 + 8.0);
    if (bytes <= static_cast<double>(max_bytes_) && entries < (std::uint64_t{1} << 32)) {
        return true;
    }
    active_ = false;
    inactive_reason_ = fmt::format(
        "the z-buffer would need {:.1f} MB for {}x{} pixels and {} polygon entries, over its "
        "limit of {:.1f} MB",
        bytes / 1e6, view().width, view().height, entries, static_cast<double>(max_bytes_) / 1e6);
    return false;
}

PixelFootprint ItemBuffer::footprint(const Scene& scene, std::uint32_t id, double& nearest) const {
    const Camera& view = eye_.camera();
    const double min_cos = min_cosine_through(scene, id, view.eye, eye_.eye_slack());
    const PolygonReach reach = polygon_reach(scene, id, min_cos, eye_.rounding());
    const Box3 region = reach.all();
    nearest = distance_to(region, view.eye) * (1.0 - 1e-12);

    const Polygon& polygon = scene.polygons[id];
    Box3 corners;
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
        corners.add(scene.corner_position(polygon, k));
    }
    bool all_in_front = true;
    for (int c = 0; c < 8; ++c) {
        all_in_front = all_in_front && view.depth(region.corner(c)) >= eye_.near_depth();
    }
    if (!all_in_front || !reach.grazing_box.empty()) {
        return eye_.footprint_of(region);
    }
    // The hull of the corners, each grown by the box's growth: tighter than the box.
    const Vec3 growth = max_components(corners.lo - reach.box.lo, reach.box.hi - corners.hi);
    std::vector<Vec3> points;
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
        const Vec3 corner = scene.corner_position(polygon, k);
        const Box3 grown = Box3{corner, corner}.grown(growth);
        for (int c = 0; c < 8; ++c) {
            points.push_back(grown.corner(c));
        }
    }
    return eye_.footprint_of(points);
}

void ItemBuffer::fill(const std::vector<PixelFootprint>& footprints) {
    const auto width = tiles_across_;
    const std::size_t tiles = width * tiles_down_;
    offsets_.assign(tiles + 1, 0);
    for (const PixelFootprint& f : footprints) {
        for (int y = f.y0; y <= f.y1; ++y) {
            for (int x = f.x0; x <= f.x1; ++x) {
                ++offsets_[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x) + 1];
            }
        }
    }
    std::partial_sum(offsets_.begin(), offsets_.end(), offsets_.begin());
    entries_.resize(offsets_.back());
    // Filled in rank order, so every list comes out nearest first.
    std::vector<std::uint32_t> cursor(offsets_.begin(), offsets_.end() - 1);
    for (std::uint32_t rank = 0; rank < footprints.size(); ++rank) {
        const PixelFootprint& f = footprints[rank];
        for (int y = f.y0; y <= f.y1; ++y) {
            for (int x = f.x0; x <= f.x1; ++x) {
                entries_[cursor[static_cast<std::size_t>(y) * width +
                                static_cast<std::size_t>(x)]++] = rank;
            }
        }
    }
}

std::optional<EyeRayPixel> ItemBuffer::pixel_of(const Ray& ray, Interval t) const {
    if (!active_) {
        return std::nullopt;
    }
    const std::optional<ViewPixel> pixel = eye_.pixel_of(ray, t);
    if (!pixel) {
        return std::nullopt;
    }
    return EyeRayPixel{pixel->x, pixel->y, length(ray.origin - view().eye)};
}

namespace {

// No hit on a polygon whose reach is `nearest` from the eye is nearer than this t, for a ray
// starting `from_eye` from the eye: |Y - O| >= |Y - E| - |O - E| (see the top). Rounded down
// generously.
double lowest_t(double nearest, double from_eye, double direction_length) {
    return (nearest * (1.0 - 1e-12) - from_eye * (1.0 + 1e-12)) / direction_length * (1.0 - 1e-12);
}

}  // namespace

std::optional<Hit> closest_hit_in_buffer(const Scene& scene, const ItemBuffer& buffer,
                                         const RaySpace& space, Interval t,
                                         const EyeRayPixel& pixel, TraceCounters& counters) {
    const Ray& ray = space.ray();
    const double direction_length = length(ray.direction);
    ClosestHitSoFar nearest(t);
    for (const std::uint32_t rank : buffer.candidates(pixel.x, pixel.y)) {
        // Strictly beyond: a polygon that might still tie the best t could have a lower id.
        if (nearest.best() &&
            lowest_t(buffer.nearest(rank), pixel.from_eye, direction_length) > nearest.reach()) {
            break;
        }
        offer_exact_hit(scene, space, buffer.polygon(rank), nearest, counters.polygon_tests);
    }
    return nearest.best();
}

std::size_t ItemBuffer::longest_list() const {
    std::size_t longest = 0;
    for (std::size_t pixel = 0; pixel + 1 < offsets_.size(); ++pixel) {
        longest = std::max<std::size_t>(longest, offsets_[pixel + 1] - offsets_[pixel]);
    }
    return longest;
}

std::size_t ItemBuffer::memory_bytes() const {
    return offsets_.capacity() * 4 + entries_.capacity() * 4 + ranked_polygons_.capacity() * 4 +
           ranked_nearest_.capacity() * 8;
}

}  // namespace rt
