// Why a pixel's list holds every polygon an eye ray through it can report a hit on.
//
// An eye ray here is one whose origin O lies on the screen (depth within 1e-9 of the screen
// distance s) and whose direction d is within angle_tolerance_ of O - E (E the eye): the
// camera's rays are, to within rounding. With t > t.min >= 0, the hit point Y = O + t d has
// depth >= depth(O) > near_depth_, and the direction of Y - E lies between those of O - E and
// d, so Y is seen from the eye within angle_tolerance_ of O: on the screen, within
// pixel_margin_ pixels of O's own pixel position.
//
// Y lies in the polygon's reach (hit_regions/polygon_reach.h), computed for the smallest |cos| a
// line through the polygon and (within eye_slack_) through the eye can make with it. The footprint
// is the screen box of that reach's part at depth >= near_depth_, widened by pixel_margin_: so O's
// pixel is in it. For a reach wholly in front of the near plane that part is the convex hull of
// the corners each grown by the reach's box growth; for one crossing it, the reach's box cut by
// the plane (its corners in front and its edges' crossings). A reach wholly behind is never hit.
//
// Each polygon's `nearest` is the distance from E to its reach's box, <= |Y - E|, and since
// |Y - O| >= |Y - E| - |O - E|, no hit on it is nearer than t = (nearest - |O - E|) / |d|.
#include "rt/accel/zbuffer/item_buffer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "rt/accel/hit_regions/polygon_reach.h"

#include <fmt/format.h>

namespace rt {

namespace {

constexpr double kDepthTolerance = 1e-9;  ///< relative, for an eye ray's origin on the screen
constexpr double kOnScreen = 1e-6;        ///< pixels an origin may lie outside the view area

}  // namespace

ItemBuffer::ItemBuffer(const Scene& scene, const Camera& view, const ZBufferSettings& settings)
    : view_(view), max_bytes_(settings.max_bytes) {
    const double s = view.screen_distance;
    if (!(view.width > 0 && view.height > 0 && s > 0.0 && view.half_width > 0.0 &&
          view.half_height > 0.0 && std::isfinite(s * view.half_width * view.half_height))) {
        active_ = false;
        inactive_reason_ = "the view has no area";
        return;
    }
    near_depth_ = s * (1.0 - 1e-6);
    angle_tolerance_ = 1e-9;
    const double wide =
        1.0 + (view.half_width * view.half_width + view.half_height * view.half_height) / (s * s);
    eye_slack_ = 1.01 * angle_tolerance_ * s * std::sqrt(wide);
    const double pixel =
        std::min(2.0 * view.half_width / view.width, 2.0 * view.half_height / view.height);
    pixel_margin_ = 1.01 * angle_tolerance_ * s * wide / pixel + 2.0 * kOnScreen +
                    1e-12 * (view.width + view.height);

    const Box3 bounds = scene.bounds();
    const double farthest = length(max_components(bounds.hi - view.eye, view.eye - bounds.lo));
    const double magnitude = std::max(bounds.magnitude(), Box3::around(view.eye).magnitude());
    rounding_ = 1e-12 * (farthest + s * std::sqrt(wide) + magnitude);

    const std::size_t count = scene.polygons.size();
    if (!fits(count, 0)) {
        return;
    }
    std::vector<Footprint> footprints(count);
    std::vector<double> nearest(count);
    std::uint64_t total = 0;
    for (std::uint32_t id = 0; id < count; ++id) {
        footprints[id] = footprint(scene, id, nearest[id]);
        const Footprint& f = footprints[id];
        if (f.x0 <= f.x1) {
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
    std::vector<Footprint> ranked(ranked_polygons_.size());
    for (std::size_t rank = 0; rank < ranked.size(); ++rank) {
        ranked[rank] = footprints[ranked_polygons_[rank]];
    }
    fill(ranked);
}

bool ItemBuffer::fits(std::size_t polygons, std::uint64_t entries) {
    const std::uint64_t pixels = static_cast<std::uint64_t>(view_.width) * view_.height;
    // Offsets and their fill cursors, the entries, and per polygon its footprint, depth and rank.
    const double bytes = 8.0 * (static_cast<double>(pixels) + 1.0) +
                         4.0 * static_cast<double>(entries) +
                         static_cast<double>(polygons) * (sizeof(Footprint) + 8.0 + 8.0);
    if (bytes <= static_cast<double>(max_bytes_) && entries < (std::uint64_t{1} << 32)) {
        return true;
    }
    active_ = false;
    inactive_reason_ = fmt::format(
        "the z-buffer would need {:.1f} MB for {}x{} pixels and {} polygon entries, over its "
        "limit of {:.1f} MB",
        bytes / 1e6, view_.width, view_.height, entries, static_cast<double>(max_bytes_) / 1e6);
    return false;
}

ItemBuffer::Footprint ItemBuffer::footprint(const Scene& scene, std::uint32_t id,
                                            double& nearest) const {
    const double min_cos = min_cosine_through(scene, id, view_.eye, eye_slack_);
    const PolygonReach reach = polygon_reach(scene, id, min_cos, rounding_);
    const Box3 region = reach.all();
    nearest = distance_to(region, view_.eye) * (1.0 - 1e-12);

    const Polygon& polygon = scene.polygons[id];
    Box3 corners;
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
        corners.add(scene.corner_position(polygon, k));
    }
    std::vector<Vec3> points;
    bool all_in_front = true;
    bool all_behind = true;
    for (int c = 0; c < 8; ++c) {
        const double depth = view_.depth(region.corner(c));
        all_in_front = all_in_front && depth >= near_depth_;
        all_behind = all_behind && depth < near_depth_;
    }
    if (all_behind) {
        return {1, 1, 0, 0};
    }
    if (all_in_front && reach.grazing_box.empty()) {
        // The hull of the corners, each grown by the box's growth: tighter than the box.
        const Vec3 growth = max_components(corners.lo - reach.box.lo, reach.box.hi - corners.hi);
        for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
            const Box3 grown =
                Box3{scene.corner_position(polygon, k), scene.corner_position(polygon, k)}.grown(
                    growth);
            for (int c = 0; c < 8; ++c) {
                points.push_back(grown.corner(c));
            }
        }
        return pixels_of(points);
    }
    for (int a = 0; a < 8; ++a) {
        const Vec3 pa = region.corner(a);
        const double da = view_.depth(pa);
        if (da >= near_depth_) {
            points.push_back(pa);
        }
        for (int bit = 1; bit < 8; bit <<= 1) {
            const Vec3 pb = region.corner(a | bit);
            const double db = view_.depth(pb);
            if ((a & bit) == 0 && (da >= near_depth_) != (db >= near_depth_)) {
                // The edge's crossing of the near plane.
                points.push_back(pa + (pb - pa) * ((near_depth_ - da) / (db - da)));
            }
        }
    }
    return pixels_of(points);
}

ItemBuffer::Footprint ItemBuffer::pixels_of(const std::vector<Vec3>& points) const {
    double x_lo = Box3::kInfinity;
    double x_hi = -Box3::kInfinity;
    double y_lo = Box3::kInfinity;
    double y_hi = -Box3::kInfinity;
    for (const Vec3& p : points) {
        double px = 0.0;
        double py = 0.0;
        view_.project(p, px, py);
        x_lo = std::min(x_lo, px);
        x_hi = std::max(x_hi, px);
        y_lo = std::min(y_lo, py);
        y_hi = std::max(y_hi, py);
    }
    // Widened by the margin, and by a relative part for the rounding of far-out projections.
    auto clamp_to = [&](double v, double sign, int size) {
        const double widened = v + sign * (pixel_margin_ + 1e-12 * std::fabs(v));
        return static_cast<int>(std::clamp(std::floor(widened), -1.0, static_cast<double>(size)));
    };
    Footprint f{clamp_to(x_lo, -1.0, view_.width), clamp_to(y_lo, -1.0, view_.height),
                clamp_to(x_hi, 1.0, view_.width), clamp_to(y_hi, 1.0, view_.height)};
    if (!(x_lo <= x_hi && y_lo <= y_hi) || f.x1 < 0 || f.y1 < 0 || f.x0 >= view_.width ||
        f.y0 >= view_.height) {
        return {1, 1, 0, 0};
    }
    f.x0 = std::max(f.x0, 0);
    f.y0 = std::max(f.y0, 0);
    f.x1 = std::min(f.x1, view_.width - 1);
    f.y1 = std::min(f.y1, view_.height - 1);
    return f;
}

void ItemBuffer::fill(const std::vector<Footprint>& footprints) {
    const std::size_t pixels = static_cast<std::size_t>(view_.width) * view_.height;
    offsets_.assign(pixels + 1, 0);
    for (const Footprint& f : footprints) {
        for (int y = f.y0; y <= f.y1; ++y) {
            for (int x = f.x0; x <= f.x1; ++x) {
                ++offsets_[static_cast<std::size_t>(y) * view_.width + x + 1];
            }
        }
    }
    std::partial_sum(offsets_.begin(), offsets_.end(), offsets_.begin());
    entries_.resize(offsets_.back());
    // Filled in rank order, so every list comes out nearest first.
    std::vector<std::uint32_t> cursor(offsets_.begin(), offsets_.end() - 1);
    for (std::uint32_t rank = 0; rank < footprints.size(); ++rank) {
        const Footprint& f = footprints[rank];
        for (int y = f.y0; y <= f.y1; ++y) {
            for (int x = f.x0; x <= f.x1; ++x) {
                entries_[cursor[static_cast<std::size_t>(y) * view_.width + x]++] = rank;
            }
        }
    }
}

std::optional<EyeRayPixel> ItemBuffer::pixel_of(const Ray& ray) const {
    if (!active_ || !is_finite(ray.origin) || !is_finite(ray.direction)) {
        return std::nullopt;
    }
    const Vec3 from_eye = ray.origin - view_.eye;
    const double depth = dot(from_eye, view_.forward);
    const double s = view_.screen_distance;
    if (!(std::fabs(depth - s) <= kDepthTolerance * s)) {
        return std::nullopt;
    }
    const double distance = length(from_eye);
    const double direction_length = length(ray.direction);
    if (!(dot(ray.direction, from_eye) > 0.0) ||
        !(length(cross(ray.direction, from_eye)) <=
          angle_tolerance_ * direction_length * distance)) {
        return std::nullopt;
    }
    double px = 0.0;
    double py = 0.0;
    view_.project(ray.origin, px, py);
    if (!(px >= -kOnScreen && px <= view_.width + kOnScreen && py >= -kOnScreen &&
          py <= view_.height + kOnScreen)) {
        return std::nullopt;
    }
    const int x = std::clamp(static_cast<int>(std::floor(px)), 0, view_.width - 1);
    const int y = std::clamp(static_cast<int>(std::floor(py)), 0, view_.height - 1);
    return EyeRayPixel{x, y, distance};
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
