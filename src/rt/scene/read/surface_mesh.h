// An optical surface file as read, before placement: what the filetypes (manual 2.5, and model
// files) have in common. Object-space coordinates; polygons are loops of vertex indices.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/core/rgb.h"
#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

// The 8-byte fields first and the small ones together at the end: 72 bytes, where the order
// of meaning took 80 in padding (a million-polygon model holds a million of these).
struct MeshPolygon {
    std::uint32_t first_corner = 0;  ///< into SurfaceMesh::corners
    std::uint32_t corner_count = 0;
    Vec3 outward;               ///< the file's outward direction; zero: the loop's own
    long attribute_offset = 0;  ///< added to the surface's attribute number
    long shape_number = -1;     ///< with marks 2, 3, 4: the shape's place in the shape file
    long number = 0;            ///< as messages name it (the file's index, or the order)
    std::int32_t texture_cell = Polygon::kNoTexture;  ///< -V: into Scene::texture_cells
    int line = 0;                                     ///< where it is defined
    PolygonMark mark = PolygonMark::Ordinary;
};
static_assert(sizeof(MeshPolygon) <= 72, "MeshPolygon's fields are ordered to leave no gaps");

/// A material a model file defines; its place in SurfaceMesh::materials is its attribute offset.
struct MeshMaterial {
    std::string name;
    std::optional<Rgb> diffuse;  ///< the file's diffuse colour, if it gives one
};

struct SurfaceMesh {
    std::vector<Vec3> vertices;
    /// The line defining each vertex, for messages; empty (or short) where the reader keeps none,
    /// and then a vertex is named by its polygon's line.
    std::vector<int> vertex_lines;
    std::vector<std::uint32_t> corners;  ///< into vertices, loop order
    std::vector<MeshPolygon> polygons;
    /// Model files only: the file's normal at each entry of `corners` (zero where it gives none),
    /// or empty when it gives none at all.
    std::vector<Vec3> corner_normals;
    std::vector<MeshMaterial> materials;  ///< model files only

    /// Appends a polygon whose corners are the given vertex indices.
    void add_polygon(MeshPolygon polygon, const std::vector<std::uint32_t>& loop) {
        polygon.first_corner = static_cast<std::uint32_t>(corners.size());
        polygon.corner_count = static_cast<std::uint32_t>(loop.size());
        corners.insert(corners.end(), loop.begin(), loop.end());
        polygons.push_back(polygon);
    }
};

}  // namespace rt
