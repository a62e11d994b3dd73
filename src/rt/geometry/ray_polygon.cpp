#include "rt/geometry/ray_polygon.h"

#include <cmath>

namespace rt {

RaySpace::RaySpace(const Ray& ray) : ray_(ray) {
    const Vec3& d = ray.direction;
    valid_ = is_finite(d) && is_finite(ray.origin) && (d.x != 0.0 || d.y != 0.0 || d.z != 0.0);
    if (!valid_) {
        return;
    }
    const double ax = std::fabs(d.x);
    const double ay = std::fabs(d.y);
    const double az = std::fabs(d.z);
    kz_ = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    kx_ = (kz_ + 1) % 3;
    ky_ = (kx_ + 1) % 3;
    shear_x_ = d[kx_] / d[kz_];
    shear_y_ = d[ky_] / d[kz_];
}

void RaySpace::project(const Vec3& corner, double& x, double& y) const {
    const Vec3 a = corner - ray_.origin;
    x = a[kx_] - shear_x_ * a[kz_];
    y = a[ky_] - shear_y_ * a[kz_];
}

// Sunday's winding number of the origin with respect to the projected loop. An edge counts
// upward when y_a <= 0 < y_b and downward when y_b <= 0 < y_a (the half-open rule moves the
// origin infinitesimally up), and only for a strictly positive (upward) or strictly negative
// (downward) edge function E = x_a*y_b - y_a*x_b (which moves it infinitesimally along +x).
// E of an edge b->a is exactly -E of a->b in floating point, and a shared corner projects to the
// same bits for every polygon, so neighbours see the same displaced origin: it lies inside exactly
// one of them. A ray in the polygon's plane projects the loop onto a line through the origin:
// every E is 0 and the ray misses, as it should.
bool ray_passes_through(const RaySpace& space, std::span<const Vec3> corners) {
    if (!space.valid() || corners.size() < 3) {
        return false;
    }
    int winding = 0;
    double xa = 0.0;
    double ya = 0.0;
    space.project(corners.back(), xa, ya);
    for (const Vec3& corner : corners) {
        double xb = 0.0;
        double yb = 0.0;
        space.project(corner, xb, yb);
        if (ya <= 0.0) {
            if (yb > 0.0 && xa * yb - ya * xb > 0.0) {
                ++winding;
            }
        } else if (yb <= 0.0 && xa * yb - ya * xb < 0.0) {
            --winding;
        }
        xa = xb;
        ya = yb;
    }
    return winding != 0;
}

std::optional<double> plane_hit(const Ray& ray, const Vec3& point, const Vec3& normal) {
    const double denominator = dot(normal, ray.direction);
    if (denominator == 0.0 || !std::isfinite(denominator)) {
        return std::nullopt;
    }
    const double t = dot(normal, point - ray.origin) / denominator;
    if (!std::isfinite(t)) {
        return std::nullopt;
    }
    return t;
}

std::optional<double> intersect_polygon(const RaySpace& space, const Scene& scene,
                                        std::uint32_t polygon, Interval t) {
    const Polygon& p = scene.polygons[polygon];
    const std::optional<double> along =
        plane_hit(space.ray(), scene.corner_position(p, 0), p.normal);
    if (!along || !(*along > t.min && *along < t.max)) {
        return std::nullopt;
    }
    // Corners are few; gather them so the winding test sees one contiguous loop.
    constexpr std::uint32_t kInline = 16;
    Vec3 inline_corners[kInline];
    std::vector<Vec3> many;
    std::span<Vec3> corners;
    if (p.corner_count <= kInline) {
        corners = std::span<Vec3>(inline_corners, p.corner_count);
    } else {
        many.resize(p.corner_count);
        corners = many;
    }
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        corners[k] = scene.corner_position(p, k);
    }
    if (!ray_passes_through(space, corners)) {
        return std::nullopt;
    }
    return along;
}

}  // namespace rt
