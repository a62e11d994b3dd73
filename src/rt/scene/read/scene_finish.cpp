// The last steps of SceneBuilder: vertex normals for smooth shading and auto-centering.
#include "rt/core/huge_pages.h"
#include "rt/scene/polygon_geometry.h"
#include "rt/scene/read/field_reader.h"
#include "rt/scene/read/scene_builder.h"

#include <fmt/format.h>

namespace rt {

void compute_vertex_normals(Scene& scene) {
    reserve_whole_huge_pages(scene.vertex_normals, scene.positions.size());
    scene.vertex_normals.assign(scene.positions.size(), Vec3{});
    for (const Polygon& p : scene.polygons) {
        if (!p.smooth) {
            continue;
        }
        const std::span<const std::uint32_t> loop(scene.corners.data() + p.first_corner,
                                                  p.corner_count);
        // Newell's length is twice the area: larger polygons weigh more.
        const Vec3 weighted = p.normal * length(newell_normal(loop, scene.positions));
        for (const std::uint32_t position : loop) {
            scene.vertex_normals[position] += weighted;
        }
    }
    for (Vec3& n : scene.vertex_normals) {
        const double l = length(n);
        n = l > 0 ? n / l : Vec3{};
    }
}

void SceneBuilder::finish(const SourceLocation& eye_at) {
    compute_vertex_normals(scene_);
    if (!scene_.model_normals.empty()) {
        scene_.model_normals.resize(scene_.corners.size(), Vec3{});  // the last corners' zeros
        scene_.corner_normals = scene_.model_normals;
    }
    SceneView& view = scene_.view;
    if (scene_.polygons.empty()) {
        diagnostics_.warn(scene_.source_files.front() + ": the scene has no polygons");
    } else if (scene_.header.center == 1) {
        view.look = scene_.bounds().centre();
        diagnostics_.note("auto-centering: look point set to " +
                          show_point(view.look.x, view.look.y, view.look.z));
    }
    if (view.eye == view.look) {
        throw InputError(eye_at, "the eye point and the look point are the same " +
                                     show_point(view.eye.x, view.eye.y, view.eye.z));
    }
}

}  // namespace rt
