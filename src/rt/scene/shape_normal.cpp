// Normals inferred from the shapes of -M (manual 2.4): "When such a polygon is intersected, we use
// the normal as calculated from the shape's parameters (radius etc.) instead of the normal to the
// polygon." The shape file does not say which way is out, so each normal is turned to agree with
// the polygon's outward normal; the radius is not needed for the direction.
#include "rt/scene/shape_normal.h"

#include <cmath>
#include <numbers>

namespace rt {

namespace {

constexpr double kTiny = 1e-12;

// The unit vector along n, turned to the side of `reference`; `reference` itself when n is too
// short (or not finite) to have a direction.
Vec3 orient_like(const Vec3& n, const Vec3& reference) {
    const double len = length(n);
    if (!(len > 0.0) || !std::isfinite(len)) {
        return reference;
    }
    const Vec3 unit = n / len;
    return dot(unit, reference) < 0.0 ? -unit : unit;
}

// The component of `point - on_axis` perpendicular to the axis; zero when the axis has no
// direction or the point is on it.
Vec3 radial_part(const Vec3& point, const Vec3& on_axis, const Vec3& unit_axis) {
    const Vec3 v = point - on_axis;
    const Vec3 radial = v - unit_axis * dot(v, unit_axis);
    return length(radial) > kTiny * length(v) ? radial : Vec3{};
}

bool unit_axis(const Shape& shape, Vec3& axis) {
    const Vec3 along = shape.second - shape.first;
    const double len = length(along);
    if (!(len > 0.0) || !std::isfinite(len)) {
        return false;
    }
    axis = along / len;
    return true;
}

Vec3 cylinder_normal(const Shape& shape, const Vec3& point, const Vec3& polygon_normal) {
    Vec3 axis;
    if (!unit_axis(shape, axis)) {
        return polygon_normal;
    }
    return orient_like(radial_part(point, shape.first, axis), polygon_normal);
}

// The cone |radial| = |along| tan(half angle) about the axis from the apex (both nappes). Its
// gradient, r^ - sign(along) tan(a) u, is the normal all along the surface line from the apex
// through the point's azimuth: r^ cos(a) - sign(along) u sin(a).
Vec3 cone_normal(const Shape& shape, const Vec3& point, const Vec3& polygon_normal) {
    Vec3 axis;
    if (!unit_axis(shape, axis)) {
        return polygon_normal;
    }
    const Vec3 radial = radial_part(point, shape.first, axis);
    if (radial == Vec3{}) {
        return polygon_normal;
    }
    const double half_angle = shape.radius_or_angle * std::numbers::pi / 180.0;
    const double side = dot(point - shape.first, axis) < 0.0 ? -1.0 : 1.0;
    const Vec3 n = normalize(radial) * std::cos(half_angle) - axis * (side * std::sin(half_angle));
    return orient_like(n, polygon_normal);
}

}  // namespace

Vec3 shape_normal(const Shape& shape, PolygonMark mark, const Vec3& point,
                  const Vec3& polygon_normal) {
    switch (mark) {
        case PolygonMark::Sphere:
            return orient_like(point - shape.first, polygon_normal);
        case PolygonMark::Cylinder:
            return cylinder_normal(shape, point, polygon_normal);
        case PolygonMark::Cone:
            return cone_normal(shape, point, polygon_normal);
        case PolygonMark::Ordinary:
        case PolygonMark::InterpolatesNormals:
            break;
    }
    return polygon_normal;
}

}  // namespace rt
