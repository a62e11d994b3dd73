// The BVH against brute force on random rays: the same polygon and the same t, bit for bit, on
// soups, spheres, boxes and the shipped twocubes scene.
#include <cstdint>
#include <filesystem>
#include <random>

#include "rt/accel/brute_force.h"
#include "rt/accel/bvh/bvh.h"
#include "rt/core/diagnostics.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "accel/accel_compare.h"
#include "support/meshes/generated_meshes.h"
#include "support/scene_builder.h"
#include "support/temp_dir.h"

namespace rt {
namespace {

using test::compare_with_brute_force;

TEST(BvhRandomRays, SoupsOfSeveralSizes) {
    for (const std::uint32_t count : {1u, 7u, 100u, 3000u}) {
        const Scene scene = test::make_triangle_soup(count, count);
        const Bvh bvh(scene);
        compare_with_brute_force(scene, bvh, 4000, count);
    }
}

TEST(BvhRandomRays, TessellatedSpheres) {
    for (const std::uint32_t count : {8u, 500u, 20000u}) {
        const Scene scene = test::make_tessellated_sphere(count);
        const Bvh bvh(scene);
        compare_with_brute_force(scene, bvh, 6000, count + 1);
    }
}

TEST(BvhRandomRays, QuadSpheresAndBoxes) {
    const Scene sphere = test::make_sphere({0.25, -0.5, 1.0}, 2.0, 12, 20, false);
    compare_with_brute_force(sphere, Bvh(sphere), 8000, 11);
    const Scene box = test::make_box({-1, -1, -1}, {1, 2, 3}, false);
    compare_with_brute_force(box, Bvh(box), 8000, 12);
    const Scene triangles = test::make_box({0, 0, 0}, {1, 1, 1}, true);
    compare_with_brute_force(triangles, Bvh(triangles), 8000, 13);
}

TEST(BvhRandomRays, TwoCubes) {
    Diagnostics diagnostics;
    const Scene scene =
        load_scene(test::source_dir() / "scenes" / "twocubes.scn", ReaderDialect{}, diagnostics);
    ASSERT_FALSE(scene.polygons.empty());
    compare_with_brute_force(scene, Bvh(scene), 20000, 14);
}

TEST(BvhRandomRays, SingleThreadedBuildGivesTheSameAnswers) {
    const Scene scene = test::make_triangle_soup(20000, 5);
    compare_with_brute_force(scene, Bvh(scene, BvhSettings{1}), 3000, 15);
}

}  // namespace
}  // namespace rt
