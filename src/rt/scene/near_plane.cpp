#include "rt/scene/near_plane.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rt {

namespace {

// A point in the camera's frame: x right, y up, z the depth in front of the eye.
using Points = std::vector<Vec3>;

// Sutherland-Hodgman: the part of the polygon where inside(p) >= 0, for a linear `inside`.
template <class Inside>
Points clip(const Points& polygon, Inside inside) {
    Points kept;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % polygon.size()];
        const double da = inside(a);
        const double db = inside(b);
        if (da >= 0.0) {
            kept.push_back(a);
        }
        if ((da >= 0.0) != (db >= 0.0)) {
            kept.push_back(a + (b - a) * (da / (da - db)));
        }
    }
    return kept;
}

double area(const Points& polygon) {
    Vec3 sum{};
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        sum += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    }
    return 0.5 * length(sum);
}

}  // namespace

NearPlaneReport polygons_before_screen(const Scene& scene) {
    const Camera camera = scene.view.camera();
    const double d = camera.screen_distance;
    const double tx = camera.half_width / d;  // the pyramid's sides: |x| <= z tx, |y| <= z ty
    const double ty = camera.half_height / d;
    // Parts exactly on the screen are seen; rounding must not count them as in front of it.
    const double near_limit = d * (1.0 - 1e-9);
    const double tiny_area = 1e-12 * d * d;
    NearPlaneReport report;
    report.nearest_depth = std::numeric_limits<double>::infinity();
    Points part;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        part.clear();
        bool all_beyond = true;  // the usual case, decided without clipping
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 v = scene.corner_position(p, k) - camera.eye;
            part.push_back({dot(v, camera.right), dot(v, camera.up), dot(v, camera.forward)});
            all_beyond = all_beyond && part.back().z >= near_limit;
        }
        if (all_beyond) {
            continue;
        }
        part = clip(part, [&](const Vec3& q) { return near_limit - q.z; });
        part = clip(part, [&](const Vec3& q) { return q.z * tx - q.x; });
        part = clip(part, [&](const Vec3& q) { return q.z * tx + q.x; });
        part = clip(part, [&](const Vec3& q) { return q.z * ty - q.y; });
        part = clip(part, [&](const Vec3& q) { return q.z * ty + q.y; });
        if (part.size() < 3 || !(area(part) > tiny_area)) {
            continue;
        }
        ++report.polygons;
        for (const Vec3& q : part) {
            report.nearest_depth = std::min(report.nearest_depth, std::max(q.z, 0.0));
        }
    }
    if (report.polygons == 0) {
        report.nearest_depth = 0.0;
    }
    return report;
}

double screendist_showing(const NearPlaneReport& report) {
    // Just below the nearest part, so that the eye rays start in front of it.
    const double below = 0.99 * report.nearest_depth;
    if (!(below > 0.0) || !std::isfinite(below)) {
        return 0.0;
    }
    const double unit = std::pow(10.0, std::floor(std::log10(below)) - 1.0);
    // The tiny nudge keeps 9.9 / 0.1 = 98.999... from flooring to 98; 0.99 leaves room below.
    return std::floor(below / unit * (1.0 + 1e-12)) * unit;
}

}  // namespace rt
