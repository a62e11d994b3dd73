#include "rt/geometry/normals.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace rt {

namespace {

constexpr double kTiny = 1e-12;

// On an edge, mean value coordinates reduce to linear interpolation between its two corners.
bool on_edge(std::span<const Vec3> corners, const Vec3& point, std::span<double> weights) {
    const std::size_t n = corners.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = corners[i];
        const Vec3& b = corners[(i + 1) % n];
        const Vec3 ab = b - a;
        const double len2 = dot(ab, ab);
        if (len2 <= 0.0) {
            continue;
        }
        const double s = dot(point - a, ab) / len2;
        const Vec3 off = point - (a + ab * s);
        if (s >= 0.0 && s <= 1.0 && dot(off, off) <= kTiny * kTiny * len2) {
            std::fill(weights.begin(), weights.end(), 0.0);
            weights[i] = 1.0 - s;
            weights[(i + 1) % n] += s;
            return true;
        }
    }
    return false;
}

Vec3 orient_like(const Vec3& n, const Vec3& reference) {
    const double len = length(n);
    if (!(len > kTiny) || !std::isfinite(len)) {
        return reference;
    }
    const Vec3 unit = n / len;
    return dot(unit, reference) < 0.0 ? -unit : unit;
}

}  // namespace

void mean_value_weights(std::span<const Vec3> corners, const Vec3& normal, const Vec3& point,
                        std::span<double> weights) {
    const std::size_t n = corners.size();
    if (on_edge(corners, point, weights)) {
        return;
    }
    // tan(alpha_i / 2) for the signed angle alpha_i between corner i and corner i+1 seen from
    // the point: |s_i x s_j| / (r_i r_j + s_i . s_j), signed by the polygon's normal.
    std::vector<double> half_tan(n);
    std::vector<double> radius(n);
    for (std::size_t i = 0; i < n; ++i) {
        radius[i] = length(corners[i] - point);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const Vec3 si = corners[i] - point;
        const Vec3 sj = corners[j] - point;
        const Vec3 c = cross(si, sj);
        const double sine = std::copysign(length(c), dot(c, normal));
        half_tan[i] = sine / (radius[i] * radius[j] + dot(si, sj));
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        weights[i] = (half_tan[(i + n - 1) % n] + half_tan[i]) / radius[i];
        sum += weights[i];
    }
    for (double& w : weights) {
        w /= sum;
    }
}

Vec3 interpolated_normal(const Scene& scene, std::uint32_t polygon, const Vec3& point) {
    const Polygon& p = scene.polygons[polygon];
    if (scene.vertex_normals.empty()) {
        return p.normal;
    }
    std::vector<Vec3> corners(p.corner_count);
    std::vector<double> weights(p.corner_count);
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        corners[k] = scene.corner_position(p, k);
    }
    mean_value_weights(corners, p.normal, point, weights);
    Vec3 blended;
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        blended += scene.vertex_normals[scene.corners[p.first_corner + k]] * weights[k];
    }
    return orient_like(blended, p.normal);
}

Vec3 shape_normal(const Shape& shape, PolygonMark mark, const Vec3& point,
                  const Vec3& polygon_normal) {
    switch (mark) {
        case PolygonMark::Sphere:
            return orient_like(point - shape.first, polygon_normal);
        case PolygonMark::Cylinder: {
            const Vec3 axis = shape.second - shape.first;
            if (!(length(axis) > kTiny)) {
                return polygon_normal;
            }
            const Vec3 u = normalize(axis);
            const Vec3 v = point - shape.first;
            return orient_like(v - u * dot(v, u), polygon_normal);
        }
        case PolygonMark::Cone: {
            const Vec3 axis = shape.second - shape.first;
            if (!(length(axis) > kTiny)) {
                return polygon_normal;
            }
            const Vec3 u = normalize(axis);
            const Vec3 v = point - shape.first;
            const double along = dot(v, u);
            const Vec3 radial = v - u * along;
            if (!(length(radial) > kTiny)) {
                return polygon_normal;
            }
            // The surface line through the point runs along u cos(a) + r sin(a); the normal is
            // the perpendicular to it in the plane of u and r, pointing away from the axis.
            const double half_angle = shape.radius_or_angle * std::numbers::pi / 180.0;
            const double side = along < 0.0 ? -1.0 : 1.0;  // the nappe behind the apex
            const Vec3 n = normalize(radial) * std::cos(half_angle) -
                           u * (side * std::sin(half_angle));
            return orient_like(n, polygon_normal);
        }
        case PolygonMark::Ordinary:
        case PolygonMark::InterpolatesNormals:
            break;
    }
    return polygon_normal;
}

}  // namespace rt
