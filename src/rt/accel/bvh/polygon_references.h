// What the BVH builder sorts: one reference per polygon, with a float box that contains every
// point at which the exact test can report a hit on it.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "rt/core/default_init_allocator.h"
#include "rt/scene/scene.h"

namespace rt::bvh {

struct Box {
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF};
    float hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};

    void grow(const Box& b) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = b.lo[k] < lo[k] ? b.lo[k] : lo[k];
            hi[k] = b.hi[k] > hi[k] ? b.hi[k] : hi[k];
        }
    }
    /// Half the surface area (the SAH only compares ratios); 0 for an empty box.
    double half_area() const {
        if (!(lo[0] <= hi[0])) {
            return 0.0;
        }
        const double dx = static_cast<double>(hi[0]) - lo[0];
        const double dy = static_cast<double>(hi[1]) - lo[1];
        const double dz = static_cast<double>(hi[2]) - lo[2];
        return dx * dy + dy * dz + dz * dx;
    }
};

struct PolygonReference {
    Box box;
    std::uint32_t polygon = 0;
    std::uint32_t triangles = 0;  ///< fan triangles: corner count - 2
    float centroid(int axis) const { return 0.5f * (box.lo[axis] + box.hi[axis]); }
};

/// Sized first and written by every thread, each its own run (polygon_references.cpp).
using ReferenceArray = std::vector<PolygonReference, UnwrittenAllocator<PolygonReference>>;

struct PolygonReferences {
    ReferenceArray bounded;
    /// Polygons with a non-finite corner or normal: no box can hold them, so every ray tests them.
    std::vector<std::uint32_t> unbounded;
    /// Largest |coordinate| of any bounded box.
    double scale = 0.0;
};

/// References for every polygon of three or more corners (the exact test misses the others).
/// Each box is the corners' box, widened for a polygon whose corners leave its plane (the exact
/// test's t is the plane's: it may lie up to 1e6 times the deviation away from the corners),
/// then rounded outward to float. `threads` (0: one per hardware thread) share the polygons; the
/// result is the same for any count.
PolygonReferences make_polygon_references(const Scene& scene, unsigned threads = 0);

}  // namespace rt::bvh
