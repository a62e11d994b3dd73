#include "rt/accel/voxel/voxel_hit_search.h"

#include <cmath>

namespace rt {

namespace {

// A long list's boxes are all asked for first, so their cache misses overlap instead of following
// each other (on a big scene they lie all over the array); a short one is not worth the pass.
void prefetch_boxes(const PolygonBoxes& boxes, std::span<const std::uint32_t> polygons) {
    if (polygons.size() < 8) {
        return;
    }
    for (const std::uint32_t id : polygons) {
        boxes.prefetch(id);
    }
}

}  // namespace

void NearestHitSearch::test(std::span<const std::uint32_t> polygons) {
    prefetch_boxes(boxes_, polygons);
    for (const std::uint32_t id : polygons) {
        if (tested_.seen(id) || !boxes_.line_may_meet(line_, id)) {
            continue;
        }
        ++counters_.polygon_tests;
        // Open at the top just above the nearest t so far: a polygon at exactly that t is still
        // returned, and wins if its id is lower (polygons arrive in voxel order, not id order).
        Interval within = t_;
        if (nearest_) {
            within.max = std::nextafter(nearest_->t, HUGE_VAL);
        }
        if (const std::optional<double> t = intersect_polygon(space_, scene_, id, within)) {
            if (!nearest_ || *t < nearest_->t || id < nearest_->polygon) {
                nearest_ = Hit{*t, id};
            }
        }
    }
}

bool AnyHitSearch::test(std::span<const std::uint32_t> polygons) {
    prefetch_boxes(boxes_, polygons);
    for (const std::uint32_t id : polygons) {
        if (tested_.seen(id) || !boxes_.line_may_meet(line_, id)) {
            continue;
        }
        ++counters_.polygon_tests;
        if (intersect_polygon(space_, scene_, id, t_)) {
            return true;
        }
    }
    return false;
}

}  // namespace rt
