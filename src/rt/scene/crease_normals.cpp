#include "rt/scene/crease_normals.h"

#include <cmath>
#include <span>

#include "rt/scene/polygon_geometry.h"

namespace rt {

void compute_crease_normals(Scene& scene, double angle) {
    // The smooth polygons around each position, as a compressed adjacency list.
    std::vector<std::uint32_t> first(scene.positions.size() + 1, 0);
    for (const Polygon& p : scene.polygons) {
        if (p.smooth) {
            for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                ++first[scene.corners[p.first_corner + k] + 1];
            }
        }
    }
    for (std::size_t i = 1; i < first.size(); ++i) {
        first[i] += first[i - 1];
    }
    std::vector<std::uint32_t> around(first.back());
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    std::vector<double> area(scene.polygons.size(), 0.0);
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        if (!p.smooth) {
            continue;
        }
        const std::span<const std::uint32_t> loop(scene.corners.data() + p.first_corner,
                                                  p.corner_count);
        area[id] = length(newell_normal(loop, scene.positions));  // larger polygons weigh more
        for (const std::uint32_t position : loop) {
            around[fill[position]++] = id;
        }
    }
    const double cos_limit = std::cos(angle);
    // A model file's normals stay: the file has decided its creases itself.
    const std::vector<Vec3>& given = scene.model_normals;
    scene.corner_normals.assign(scene.corners.size(), Vec3{});
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        if (!p.smooth) {
            continue;
        }
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            if (!given.empty() && given[p.first_corner + k] != Vec3{}) {
                scene.corner_normals[p.first_corner + k] = given[p.first_corner + k];
                continue;
            }
            const std::uint32_t position = scene.corners[p.first_corner + k];
            Vec3 sum;
            for (std::uint32_t i = first[position]; i < first[position + 1]; ++i) {
                const Polygon& other = scene.polygons[around[i]];
                if (dot(other.normal, p.normal) >= cos_limit) {
                    sum += other.normal * area[around[i]];
                }
            }
            const double l = length(sum);
            scene.corner_normals[p.first_corner + k] = l > 0.0 ? sum / l : p.normal;
        }
    }
}

}  // namespace rt
