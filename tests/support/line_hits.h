// Counting where a line meets a mesh, for watertightness tests: every polygon tested on its own
// over the whole line, and the rays that stress shared edges and corners.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "rt/core/ray.h"
#include "rt/scene/scene.h"

namespace rt::test {

struct LineHits {
    int count = 0;
    int signed_winding = 0;  ///< entering and leaving cancel on a consistently oriented mesh
    std::vector<std::uint32_t> polygons;
    std::vector<double> depths;
};

/// Every polygon the ray's whole line (t in +-kBeyondAnyScene) passes through; also checks that
/// intersect_polygon and winding_number agree on each polygon.
LineHits hits_along(const Scene& scene, const Ray& ray);

/// "ray from (x, y, z) along (dx, dy, dz)" with every digit, to reproduce a failure.
std::string describe(const Ray& ray);

/// A line meets a closed convex mesh 0 or 2 times, its signed windings cancel, and two hits at
/// distinct depths are one entering (nearer) and one leaving (farther).
void expect_even_crossing(const Scene& scene, const Ray& ray);

/// A line through the inside of a closed convex mesh meets it exactly twice.
void expect_two_crossings(const Scene& scene, const Ray& ray);

/// Every loop turns the way its outward normal says (else the signed winding means nothing).
void expect_consistent_loops(const Scene& scene);

Vec3 random_unit(std::mt19937_64& random);

/// The ray through `through` along `direction`, starting 8 directions back: when every input is
/// a small dyadic number, origin, corner - origin and the shear are exact, so the ray's line
/// passes exactly through `through`.
Ray ray_through(const Vec3& through, const Vec3& direction);

/// Directions whose components are 0, +-1/4, +-1/2 or +-1 (so exact shears), in every octant,
/// including the axis-parallel and diagonal ones.
std::vector<Vec3> dyadic_directions();

/// The 8 corners of the box [lo, hi].
std::vector<Vec3> box_corners(const Vec3& lo, const Vec3& hi);

}  // namespace rt::test
