// The bound on rays per sample behind the exploding-tree warning, against sums worked by hand.
#include "rt/render/ray_tree_bound.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// A box of one attribute; lghtick 0, so no shadow feelers and, with a diffuse weight, diffuse rays.
Scene box(double specular, double transmission, int maxdepth) {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, false);
    scene.attributes[0].specular = specular;
    scene.attributes[0].transmission = transmission;
    scene.attributes[0].diffuse = 0.0;
    scene.header.maxdepth = maxdepth;
    scene.header.lghtick = 0;
    return scene;
}

TEST(RayTreeBound, AMirrorSendsOneRayALevel) {
    const RayTreeBound b = ray_tree_bound(box(0.9, 0.0, 10), {});
    EXPECT_EQ(b.rays_per_sample, 10.0);
    EXPECT_EQ(b.widest_branching, 1.0);
}

TEST(RayTreeBound, GlassThatAlsoReflectsDoublesEveryLevel) {
    // 1 + 2 + 4 + ... + 2^29 = 2^30 - 1.
    const RayTreeBound b = ray_tree_bound(box(0.5, 0.5, 30), {});
    EXPECT_EQ(b.rays_per_sample, 1073741823.0);
    EXPECT_GT(b.rays_per_sample, kExplodingRayTree);
    EXPECT_EQ(b.widest_branching, 2.0);
    ShadingSettings no_reflection;
    no_reflection.reflection = false;  // -Dr: only the refracted ray is left
    EXPECT_EQ(ray_tree_bound(box(0.5, 0.5, 30), no_reflection).rays_per_sample, 30.0);
}

TEST(RayTreeBound, DistributedLobesSendNByNRaysDownToMaxdist) {
    Scene scene = box(0.5, 0.0, 3);
    scene.attributes[0].reflect_cone_degrees = 10.0;
    scene.view.sample_resolution_x = 2;
    scene.view.sample_resolution_y = 2;
    scene.header.maxdist = 1.0;
    // Depth 1 distributes 4 rays; depth 2 (beyond maxdist) sends one each: 1 + 4 + 4.
    EXPECT_EQ(ray_tree_bound(scene, {}).rays_per_sample, 9.0);
    ShadingSettings axis_only;
    axis_only.sampling.distribute = false;  // -Dd
    EXPECT_EQ(ray_tree_bound(scene, axis_only).rays_per_sample, 3.0);
}

TEST(RayTreeBound, EveryRayCountsItsShadowFeelers) {
    Scene scene = box(0.5, 0.5, 3);
    scene.attributes[0].emission = 1.0;  // every face an emitter: 6 point lights at lghtick 2
    scene.header.lghtick = 2;
    // (1 + 2 + 4) rays, each with 6 feelers.
    EXPECT_EQ(ray_tree_bound(scene, {}).rays_per_sample, 7.0 * 7.0);
}

}  // namespace
}  // namespace rt
