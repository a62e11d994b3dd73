// Builds small scenes by hand for tests: polygons from corner lists, sharing identical corners,
// and a few closed meshes (box, sphere) and open ones (fan) made of shared vertices.
#pragma once

#include <cstdint>
#include <vector>

#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt::test {

class SceneBuilder {
public:
    SceneBuilder();
    Scene& scene() { return scene_; }

    /// Adds a polygon with these corners in loop order; a corner bit-identical to an existing
    /// position shares it. The normal is Newell's, turned to agree with `outward` (unless that is
    /// zero). Fills corners, polygons and polygon_origin. Returns the polygon's id.
    std::uint32_t add_polygon(const std::vector<Vec3>& corners, const Vec3& outward = {},
                              std::uint32_t attribute = 0);

    /// Sets every vertex normal to the normalised sum of the normals of the polygons around it,
    /// and marks every polygon smooth.
    void smooth_vertex_normals();

private:
    std::uint32_t position_of(const Vec3& p);
    Scene scene_;
};

/// Newell's normal of a loop (unit; zero for a degenerate loop).
Vec3 newell_normal(const std::vector<Vec3>& corners);

/// The closed box [lo, hi] with outward normals: 6 quads, or 12 triangles if `triangles`.
Scene make_box(const Vec3& lo, const Vec3& hi, bool triangles);

/// A closed UV sphere with outward normals: `slices` triangles around each pole, quads (or two
/// triangles each, if `triangles`) in between; 2 <= stacks, 3 <= slices.
Scene make_sphere(const Vec3& centre, double radius, int stacks, int slices, bool triangles);

/// A fan of `count` triangles in the plane z = 0 around the corner (0,0,0), normals along +z.
Scene make_fan(int count, double radius);

}  // namespace rt::test
