// A cheap first look before the exact ray-polygon test: each polygon's bounding box, grown a
// little and stored as floats rounded outward (24 bytes a polygon, next to each other in memory),
// tested against the ray's line. A line that misses the grown box cannot have the polygon around
// it in the exact test (which needs the line to pass through the polygon's projection, up to
// rounding far below the growth), so the polygon is skipped without touching the scene's records.
// It only ever skips polygons the exact test would miss: the answers stay brute force's.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "rt/accel/voxel/box.h"
#include "rt/geometry/ray.h"

namespace rt {

/// The ray's line, prepared once per ray for many box tests.
struct LineProbe {
    explicit LineProbe(const Ray& ray);
    Vec3 origin;
    Vec3 inverse;        ///< 1 / direction (0 where the direction is 0: see `parallel`)
    bool parallel[3]{};  ///< direction component exactly 0
};

class PolygonBoxes {
public:
    /// `growth`: how far each box is grown on every side (the world's 2^-24 serves well).
    PolygonBoxes(const Scene& scene, double growth);

    /// False only if the line certainly misses the polygon.
    bool line_may_meet(const LineProbe& line, std::uint32_t polygon) const {
        const float* b = boxes_.data() + 6 * static_cast<std::size_t>(polygon);
        double near = -HUGE_VAL;
        double far = HUGE_VAL;
        for (int a = 0; a < 3; ++a) {
            const double lo = b[a];
            const double hi = b[3 + a];
            if (line.parallel[a]) {
                if (line.origin[a] < lo || line.origin[a] > hi) {
                    return false;
                }
                continue;
            }
            double t0 = (lo - line.origin[a]) * line.inverse[a];
            double t1 = (hi - line.origin[a]) * line.inverse[a];
            if (t0 > t1) {
                std::swap(t0, t1);
            }
            near = near > t0 ? near : t0;
            far = far < t1 ? far : t1;
        }
        return near <= far;
    }

    /// Asks the cache for the polygon's box ahead of line_may_meet.
    void prefetch(std::uint32_t polygon) const {
        __builtin_prefetch(boxes_.data() + 6 * static_cast<std::size_t>(polygon));
    }

    std::size_t memory_bytes() const { return boxes_.capacity() * sizeof(float); }

private:
    std::vector<float> boxes_;  ///< per polygon: lo x y z, hi x y z
};

}  // namespace rt
