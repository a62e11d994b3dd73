#include "rt/scene/read/stage_meshes.h"

namespace rt {

SurfaceMesh checkerboard_mesh(int n, double half) {
    SurfaceMesh mesh;
    const double step = 2.0 * half / n;
    for (int i = 0; i <= n; ++i) {
        for (int k = 0; k <= n; ++k) {
            mesh.vertices.push_back({-half + step * k, 0.0, -half + step * i});
        }
    }
    const auto at = [n](int i, int k) { return static_cast<std::uint32_t>(i * (n + 1) + k); };
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < n; ++k) {
            MeshPolygon p;
            p.outward = {0, 1, 0};
            p.attribute_offset = (i + k) % 2;
            p.number = i * n + k;
            mesh.add_polygon(p, {at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1)});
        }
    }
    return mesh;
}

SurfaceMesh square_light_mesh(double half) {
    SurfaceMesh mesh;
    mesh.vertices = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
    MeshPolygon p;
    p.outward = {0, -1, 0};
    mesh.add_polygon(p, {0, 1, 2, 3});
    return mesh;
}

}  // namespace rt
