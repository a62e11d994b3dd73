// Synthetic triangle meshes of any size, for the accelerator tests and benchmarks: a closed
// tessellated sphere (coherent, shared vertices), a random triangle soup (independent triangles
// whose size shrinks with their number, as the measurements suppose) and a sphere of
// even triangles.
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

/// A unit sphere of about `triangles` triangles of even size (rt_voxel_bench): each face of a cube
/// cut into an n x n grid of squares, two triangles each, every vertex pushed out to the sphere;
/// the faces' grids do not share their border vertices. (A UV sphere's poles, where hundreds of
/// slivers meet, would measure the poles rather than the method.)
Scene make_cube_sphere(std::uint32_t triangles);

/// The same polygons with their positions spread over `spread` times as many slots in random
/// order (the other slots copy position 0), so that a triangle's corners lie far apart in
/// Scene::positions, as in a model whose faces index vertices anywhere.
void scatter_positions(Scene& scene, std::uint32_t spread, std::uint64_t seed);

}  // namespace rt::test
