#include "rt/scene/polygon_geometry.h"

#include <algorithm>

namespace rt {

Vec3 newell_normal(std::span<const std::uint32_t> loop, std::span<const Vec3> vertices) {
    Vec3 n;
    if (loop.empty()) {
        return n;
    }
    // Relative to the first corner, so that far-off polygons keep their precision.
    const Vec3 origin = vertices[loop[0]];
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec3 a = vertices[loop[i]] - origin;
        const Vec3 b = vertices[loop[(i + 1) % loop.size()]] - origin;
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

std::string_view degeneracy(std::span<const std::uint32_t> loop, std::span<const Vec3> vertices,
                            const Vec3& newell) {
    int distinct = 0;
    Vec3 seen[2];
    Vec3 lo;
    Vec3 hi;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec3& p = vertices[loop[i]];
        lo = i == 0 ? p : min_components(lo, p);
        hi = i == 0 ? p : max_components(hi, p);
        if (distinct < 3 &&
            std::none_of(seen, seen + distinct, [&](const Vec3& q) { return q == p; })) {
            if (distinct < 2) {
                seen[distinct] = p;
            }
            ++distinct;
        }
    }
    if (distinct < 3) {
        return "fewer than 3 distinct corners";
    }
    // Collinear corners leave only rounding in Newell's sums: compare with the loop's size.
    const Vec3 extent = hi - lo;
    const double size = std::max({extent.x, extent.y, extent.z});
    if (length(newell) <= 1e-10 * size * size) {
        return "zero area";
    }
    return {};
}

}  // namespace rt
