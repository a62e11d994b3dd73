#include "rt/scene/textured_point.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

double cross2(double ax, double ay, double bx, double by) {
    return ax * by - ay * bx;
}

// (s, t) in [0, 1]^2 with p = a + s (b - a) + t (d - a) + s t (a - b + c - d), for the quad
// a b c d in 2D (a at (0, 0), b at (1, 0), c at (1, 1), d at (0, 1)): the root of the quadratic
// in t that lies in the quad, or the nearest.
void inverse_bilinear(const double a[2], const double b[2], const double c[2], const double d[2],
                      const double p[2], double& s, double& t) {
    const double ex = b[0] - a[0];
    const double ey = b[1] - a[1];
    const double fx = d[0] - a[0];
    const double fy = d[1] - a[1];
    const double gx = a[0] - b[0] + c[0] - d[0];
    const double gy = a[1] - b[1] + c[1] - d[1];
    const double hx = p[0] - a[0];
    const double hy = p[1] - a[1];
    const double k2 = cross2(gx, gy, fx, fy);
    const double k1 = cross2(ex, ey, fx, fy) + cross2(hx, hy, gx, gy);
    const double k0 = cross2(hx, hy, ex, ey);
    const auto s_for = [&](double tt) {
        const double along_x = ex + gx * tt;
        const double along_y = ey + gy * tt;
        // The larger component divides best.
        return std::fabs(along_x) >= std::fabs(along_y) ? (hx - fx * tt) / along_x
                                                        : (hy - fy * tt) / along_y;
    };
    // A parallelogram (k2 = 0 relative to its size) is linear in t.
    if (std::fabs(k2) <= 1e-12 * std::fabs(k1)) {
        t = -k0 / k1;
        s = s_for(t);
    } else {
        const double w = std::sqrt(std::max(0.0, k1 * k1 - 4.0 * k0 * k2));
        t = (-k1 - w) / (2.0 * k2);
        s = s_for(t);
        if (!(s >= -1e-9 && s <= 1 + 1e-9 && t >= -1e-9 && t <= 1 + 1e-9)) {
            t = (-k1 + w) / (2.0 * k2);
            s = s_for(t);
        }
    }
    s = std::clamp(std::isfinite(s) ? s : 0.0, 0.0, 1.0);
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
}

}  // namespace

GridCoordinates grid_coordinates(const Scene& scene, std::uint32_t polygon, const Vec3& point) {
    const Polygon& p = scene.polygons[polygon];
    const TextureCell& cell = scene.texture_cells[static_cast<std::size_t>(p.texture_cell)];
    // In the cell's plane, from its first corner: corners (r, c) (r, c+1) (r+1, c+1) (r+1, c).
    const Vec3 origin = scene.corner_position(p, 0);
    double flat[4][2];
    for (std::uint32_t k = 0; k < 4; ++k) {
        const Vec3 q = scene.corner_position(p, k) - origin;
        flat[k][0] = dot(q, cell.tangent_u);
        flat[k][1] = dot(q, cell.tangent_v);
    }
    const double at[2] = {dot(point - origin, cell.tangent_u), dot(point - origin, cell.tangent_v)};
    double s = 0.0;
    double t = 0.0;
    inverse_bilinear(flat[0], flat[1], flat[2], flat[3], at, s, t);
    return {cell.column + s, cell.row + t};
}

Vec3 normal_map_normal(const Rgb& texel, const Vec3& normal, const Vec3& tangent_u,
                       const Vec3& tangent_v) {
    // The frame around the (perhaps bent) normal: u made perpendicular to it, then v.
    const Vec3 u = tangent_u - normal * dot(tangent_u, normal);
    if (!(dot(u, u) > 0.0)) {
        return normal;
    }
    const Vec3 t = normalize(u);
    const Vec3 v = tangent_v - normal * dot(tangent_v, normal) - t * dot(tangent_v, t);
    const Vec3 b = dot(v, v) > 0.0 ? normalize(v) : cross(normal, t);
    const Vec3 mapped =
        t * (2.0 * texel.r - 1.0) - b * (2.0 * texel.g - 1.0) + normal * (2.0 * texel.b - 1.0);
    // A pixel that says nothing, or points into the surface, leaves the normal as it was.
    return dot(mapped, normal) > 0.0 ? normalize(mapped) : normal;
}

TexturedPoint textured_point(const Scene& scene, std::uint32_t polygon, const Vec3& point) {
    const Polygon& p = scene.polygons[polygon];
    const TextureCell& cell = scene.texture_cells[static_cast<std::size_t>(p.texture_cell)];
    TexturedPoint out{element_normal(cell, p.normal, point), cell.color};
    const TextureGrid& grid = scene.texture_grids[cell.grid];
    if (!grid.has_images()) {
        return out;
    }
    const GridCoordinates at = grid_coordinates(scene, polygon, point);
    const auto sample = [&](std::int32_t image) {
        const TextureImage& picture = scene.texture_images[static_cast<std::size_t>(image)];
        return sample_bilinear(picture, at.u / grid.columns * picture.width,
                               at.v / grid.rows * picture.height);
    };
    if (grid.colour_map != TextureGrid::kNoImage) {
        out.color = out.color * sample(grid.colour_map);
    }
    if (grid.normal_map != TextureGrid::kNoImage) {
        out.normal =
            normal_map_normal(sample(grid.normal_map), out.normal, cell.tangent_u, cell.tangent_v);
    }
    return out;
}

Rgb surface_color(const Scene& scene, std::uint32_t polygon, const Vec3& point) {
    const Polygon& p = scene.polygons[polygon];
    const Rgb& color = scene.attribute_of(p).color;
    if (p.texture_cell == Polygon::kNoTexture) {
        return color;
    }
    const TextureCell& cell = scene.texture_cells[static_cast<std::size_t>(p.texture_cell)];
    if (!scene.texture_grids[cell.grid].has_images()) {
        return color * cell.color;
    }
    return color * textured_point(scene, polygon, point).color;
}

}  // namespace rt
