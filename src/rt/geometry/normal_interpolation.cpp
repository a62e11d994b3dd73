// Normal interpolation over polygons of any number of corners. The manual promises "a fast normal
// interpolation scheme for polygons of any number of edges" without saying which; we use mean
// value coordinates (Floater 2003) in the robust form of Hormann and Floater ("Mean value
// coordinates for arbitrary planar polygons", 2006), because they are defined for convex AND
// concave polygons, reduce to ordinary barycentric coordinates on triangles, are linear along each
// edge (so neighbouring polygons agree on their shared edge: no shading seams) and reproduce
// linear functions. They are computed in 3D with signed areas measured along the polygon's normal,
// which is the same as computing them in the polygon's plane.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "rt/geometry/normals.h"

namespace rt {

namespace {

// Relative size below which a point counts as on a corner or an edge.
constexpr double kTiny = 1e-12;

// Scratch space without a heap allocation for the usual few corners.
template <class T>
class Scratch {
public:
    explicit Scratch(std::size_t n) : size_(n) {
        if (n > inline_.size()) {
            heap_.resize(n);
        }
    }
    std::span<T> get() {
        return heap_.empty() ? std::span<T>(inline_.data(), size_) : std::span<T>(heap_);
    }

private:
    std::array<T, 32> inline_{};
    std::vector<T> heap_;
    std::size_t size_;
};

void fill_equal(std::span<double> weights) {
    std::fill(weights.begin(), weights.end(), 1.0 / static_cast<double>(weights.size()));
}

void fill_corner(std::span<double> weights, std::size_t corner) {
    std::fill(weights.begin(), weights.end(), 0.0);
    weights[corner] = 1.0;
}

// On edge i -> i+1 the coordinates are the linear interpolation between its two corners.
void fill_edge(std::span<double> weights, std::size_t i, double ri, double rj) {
    std::fill(weights.begin(), weights.end(), 0.0);
    weights[i] = rj / (ri + rj);
    weights[(i + 1) % weights.size()] = ri / (ri + rj);
}

// tan(alpha_i / 2), alpha_i the signed angle at `point` between corners i and i+1, as
// (r_i r_j - s_i.s_j) / (|s_i x s_j| signed by the normal); 0 for a zero angle. Sets `on_edge`
// when the angle is a straight one (the point lies on the edge).
double half_angle_tangent(const Vec3& si, const Vec3& sj, double ri, double rj, const Vec3& normal,
                          bool& on_edge) {
    const double area = dot(cross(si, sj), normal);
    const double cosine_part = dot(si, sj);
    if (std::fabs(area) <= kTiny * ri * rj) {
        on_edge = cosine_part < 0.0;
        return 0.0;
    }
    return (ri * rj - cosine_part) / area;
}

}  // namespace

void mean_value_weights(std::span<const Vec3> corners, const Vec3& normal, const Vec3& point,
                        std::span<double> weights) {
    const std::size_t n = corners.size();
    if (n == 0 || weights.size() < n) {
        return;
    }
    weights = weights.first(n);
    Scratch<double> radius_space(n);
    Scratch<double> tangent_space(n);
    const std::span<double> radius = radius_space.get();
    const std::span<double> tangent = tangent_space.get();
    double largest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        radius[i] = length(corners[i] - point);
        largest = std::max(largest, radius[i]);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (radius[i] <= kTiny * largest) {
            fill_corner(weights, i);
            return;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        bool on_edge = false;
        tangent[i] = half_angle_tangent(corners[i] - point, corners[j] - point, radius[i],
                                        radius[j], normal, on_edge);
        if (on_edge) {
            fill_edge(weights, i, radius[i], radius[j]);
            return;
        }
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        weights[i] = (tangent[(i + n - 1) % n] + tangent[i]) / radius[i];
        sum += weights[i];
    }
    if (sum == 0.0 || !std::isfinite(sum)) {
        fill_equal(weights);
        return;
    }
    for (double& w : weights) {
        w /= sum;
    }
}

void polygon_weights(const PolygonView& polygon, const Vec3& point, std::span<double> weights) {
    Scratch<Vec3> corner_space(polygon.corner_count());
    const std::span<Vec3> corners = corner_space.get();
    for (std::uint32_t k = 0; k < polygon.corner_count(); ++k) {
        corners[k] = polygon.corner(k);
    }
    mean_value_weights(corners, polygon.normal, point, weights);
}

Vec3 interpolated_normal(const PolygonView& polygon, const CornerNormals& normals,
                         const Vec3& point) {
    if (normals.empty() || polygon.corner_count() == 0) {
        return polygon.normal;
    }
    Scratch<double> weight_space(polygon.corner_count());
    const std::span<double> weights = weight_space.get();
    polygon_weights(polygon, point, weights);
    const bool per_corner = !normals.per_corner.empty();
    const bool per_vertex = !normals.per_vertex.empty();
    Vec3 blended;
    for (std::uint32_t k = 0; k < polygon.corner_count(); ++k) {
        // A zero corner normal is "none given": the vertex normal stands in.
        const bool own = per_corner && normals.per_corner[k] != Vec3{};
        const Vec3 n = own          ? normals.per_corner[k]
                       : per_vertex ? normals.per_vertex[polygon.corner_ids[k]]
                                    : Vec3{};
        blended += n * weights[k];
    }
    const double len = length(blended);
    if (!(len > kTiny) || !std::isfinite(len)) {
        return polygon.normal;
    }
    return blended / len;
}

}  // namespace rt
