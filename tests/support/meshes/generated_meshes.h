// Synthetic triangle meshes of any size, for the accelerator lab and the accelerator tests: a
// closed tessellated sphere (coherent, shared vertices) and a random triangle soup (independent
// triangles whose size shrinks with their number, as the measurements suppose).
#pragma once

#include <cstdint>

#include "rt/scene/scene.h"

namespace rt::test {

/// A closed UV sphere of about `triangles` triangles (at least 8) around `centre`: shared
/// positions, outward unit normals, a view looking at it from -z.
Scene make_tessellated_sphere(std::uint32_t triangles, const Vec3& centre = {},
                              double radius = 1.0);

/// `triangles` random triangles in the unit cube [0,1]^3, reproducible from `seed`. Each has
/// corners within a cube of side 2 * count^(-1/3) around a random point, so the soup's density of
/// surface stays about the same whatever the count. Degenerate draws are redrawn.
Scene make_triangle_soup(std::uint32_t triangles, std::uint64_t seed = 1);

}  // namespace rt::test
