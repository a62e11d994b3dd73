// One polygon as the geometry routines see it, without the scene that holds it: the loop of its
// corners (indices into shared positions, so that neighbours share a corner's bits) and its unit
// normal, and the normals at its corners for smooth shading. Scene::polygon_view() and
// Scene::normals_of() make them; keeping the scene out lets geometry/ sit below scene/.
#pragma once

#include <cstdint>
#include <span>

#include "rt/core/vec3.h"

namespace rt {

struct PolygonView {
    std::span<const Vec3> positions;            ///< shared by all the polygons
    std::span<const std::uint32_t> corner_ids;  ///< this polygon's corners in loop order
    Vec3 normal;                                ///< unit geometric normal, pointing outward

    std::uint32_t corner_count() const { return static_cast<std::uint32_t>(corner_ids.size()); }
    const Vec3& corner(std::uint32_t k) const { return positions[corner_ids[k]]; }
};

/// The normals at a polygon's corners: its own, one per corner in loop order (`per_corner`), where
/// they are not zero, else the ones shared per vertex, indexed like the positions (`per_vertex`);
/// both empty when there are none.
struct CornerNormals {
    std::span<const Vec3> per_vertex;
    std::span<const Vec3> per_corner;

    bool empty() const { return per_vertex.empty() && per_corner.empty(); }
};

}  // namespace rt
