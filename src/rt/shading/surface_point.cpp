#include "rt/shading/surface_point.h"

#include "rt/geometry/normals.h"
#include "rt/scene/shape_normal.h"
#include "rt/scene/textured_point.h"

namespace rt {

namespace {

Vec3 outward_shading_normal(const Scene& scene, std::uint32_t id, const Vec3& point) {
    const Polygon& p = scene.polygons[id];
    if (p.shape != Polygon::kNoShape && p.mark != PolygonMark::Ordinary &&
        p.mark != PolygonMark::InterpolatesNormals) {
        return shape_normal(scene.shapes[static_cast<std::size_t>(p.shape)], p.mark, point,
                            p.normal);
    }
    if (p.smooth) {
        return interpolated_normal(scene.polygon_view(id), scene.normals_of(id), point);
    }
    return p.normal;
}

}  // namespace

SurfacePoint describe_hit(const Scene& scene, const ShadingSettings& settings, const Ray& ray,
                          const Hit& hit) {
    const Polygon& p = scene.polygons[hit.polygon];
    SurfacePoint s;
    s.position = ray.at(hit.t);
    s.polygon = hit.polygon;
    s.attribute = &scene.attribute_of(p);
    s.front = dot(ray.direction, p.normal) < 0.0;
    s.facing_normal = s.front ? p.normal : -p.normal;
    Vec3 shading;
    if (p.texture_cell != Polygon::kNoTexture) {
        const TexturedPoint textured = textured_point(scene, hit.polygon, s.position);
        shading = textured.normal;
        s.color = s.attribute->color * textured.color;
    } else {
        shading = outward_shading_normal(scene, hit.polygon, s.position);
        s.color = s.attribute->color;
    }
    s.shading_normal = s.front ? shading : -shading;
    // An interpolated or mapped normal may lean past the silhouette; never let it face away from
    // the ray.
    if (settings.correct_smoothing && dot(s.shading_normal, s.facing_normal) <= 0.0) {
        s.shading_normal = s.facing_normal;
    }
    const bool forced_opaque = settings.smooth_shaded_opaque && p.smooth;
    s.transmission = forced_opaque ? 0.0 : s.attribute->transmission;
    return s;
}

}  // namespace rt
