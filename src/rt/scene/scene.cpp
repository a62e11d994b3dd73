#include "rt/scene/scene.h"

#include "rt/core/huge_pages.h"

namespace rt {

SourceLocation Scene::origin_of(std::uint32_t polygon) const {
    const SourceRef& ref = polygon_origin.at(polygon);
    return {source_files.at(ref.file), static_cast<int>(ref.line), 0};
}

CornerNormals Scene::normals_of(std::uint32_t polygon) const {
    if (vertex_normals.size() < positions.size()) {
        return {};
    }
    if (corner_normals.size() != corners.size()) {
        return {vertex_normals, {}};
    }
    const Polygon& p = polygons[polygon];
    return {vertex_normals, {corner_normals.data() + p.first_corner, p.corner_count}};
}

Box3 Scene::bounds() const {
    if (positions.empty()) {
        return Box3::around(Vec3{});
    }
    Box3 box = Box3::around(positions.front());
    for (const Vec3& p : positions) {
        box.add(p);
    }
    return box;
}

void move_to_huge_pages(Scene& scene) {
    move_to_huge_pages(scene.positions);
    move_to_huge_pages(scene.corners);
    move_to_huge_pages(scene.polygons);
}

}  // namespace rt
