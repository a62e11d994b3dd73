// Rays starting on polygons (reflected and refracted rays, shadow feelers) against brute force,
// for every intersection method and exit culling over them: the same t bits and polygon from
// closest_hit, the same occluded(), on closed boxes, spheres, a soup, boxes on a floor, and
// polygons lying in voxel faces. The z-buffer has its own file
// (zbuffer_rays_from_polygons_test.cpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/bvh/bvh.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/accel/make_accelerator.h"
#include "rt/accel/octree/octree.h"
#include "rt/accel/seads/seads.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"
#include "accel/grid_test_support.h"
#include "accel/surface_rays.h"
#include "support/meshes/generated_meshes.h"

namespace rt::test {
namespace {

struct Method {
    std::string name;
    std::function<std::unique_ptr<Accelerator>(const Scene&)> make;
    /// False for -on, which may take a farther polygon found in an earlier voxel: then only
    /// hit or miss, occlusion, and a t never nearer than brute force's must agree.
    bool exact = true;
};

AccelSettings settings(AccelKind kind, int depth_or_side, bool level_order, bool near_hits) {
    AccelSettings s;
    s.kind = kind;
    s.octree.depth = depth_or_side;
    s.seads_resolution = depth_or_side;
    s.octree.level_order = level_order;
    s.accept_near_hits = near_hits;
    return s;
}

std::vector<Method> every_method(const Scene& scene) {
    const int depth = suggested_octree_depth(scene.polygons.size());
    const int side = suggested_seads_resolution(scene.polygons.size());
    const auto made = [](AccelSettings s) {
        return [s](const Scene& sc) { return make_accelerator(sc, s); };
    };
    std::vector<Method> methods{
        {"bvh", [](const Scene& sc) { return make_bvh(sc); }},
        {"octree", made(settings(AccelKind::Octree, depth, false, false))},
        {"octree deep", made(settings(AccelKind::Octree, depth + 4, false, false))},
        {"octree -op", made(settings(AccelKind::Octree, depth + 2, true, false))},
        {"octree -on", made(settings(AccelKind::Octree, depth + 2, false, true)), false},
        {"octree -op -on", made(settings(AccelKind::Octree, depth + 2, true, true)), false},
        {"seads", made(settings(AccelKind::Seads, side, false, false))},
        {"seads fine", made(settings(AccelKind::Seads, 4 * side, false, false))},
        {"seads -on", made(settings(AccelKind::Seads, 2 * side, false, true)), false},
        // Exit culling culls rays leaving a polygon by that polygon's directions and guards
        // (leaving_table.h): these show that wrapping changes no answer.
        {"exit culling over brute force",
         [](const Scene& sc) { return std::make_unique<ExitCulling>(sc, make_brute_force(sc)); }},
        {"exit culling over bvh",
         [](const Scene& sc) { return std::make_unique<ExitCulling>(sc, make_bvh(sc)); }},
    };
    return methods;
}

struct SceneCase {
    std::string name;
    Scene scene;
    /// Closed and convex with outward normals: entering rays all hit, leaving ones all miss.
    bool convex_closed = false;
    /// The share of rays brute force must find a hit for.
    double minimum_hit_share = 0.0;
};

std::vector<SceneCase> scene_cases() {
    std::vector<SceneCase> cases;
    cases.push_back({"closed box of quads", make_box({-1, -2, -3}, {1, 2, 3}, false), true, 0.35});
    cases.push_back({"closed box of triangles", make_box({0, 0, 0}, {1, 1, 1}, true), true, 0.35});
    cases.push_back(
        {"sphere of quads", make_sphere({0.1, 0.2, 0.3}, 2.0, 12, 18, false), true, 0.4});
    cases.push_back({"tessellated sphere", make_tessellated_sphere(3000), true, 0.4});
    cases.push_back({"soup", make_soup(31, 400), false, 0.08});
    cases.push_back({"boxes on a floor", make_boxes(32, 15), false, 0.4});
    return cases;
}

// On a closed convex solid with outward normals, a ray from a face's inside (not an edge) going
// into the solid meets another face, and one leaving it meets nothing: true whatever brute
// force says, so it checks the rays and brute force. Directions within 0.05 of the face's
// plane are left out, so the origin's rounding cannot put a ray on the other side.
void expect_convex_solid_answers(const Scene& scene, const std::vector<SurfaceRay>& rays,
                                 const std::vector<Answer>& want) {
    int entering = 0;
    int entering_hits = 0;
    int leaving = 0;
    int leaving_hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const SurfaceRay& r = rays[i];
        const double along = dot(r.ray.direction, scene.polygons[r.from].normal);
        if (r.kind == SurfaceRayKind::Feeler || r.on_edge || std::fabs(along) <= 0.05) {
            continue;
        }
        (along < 0 ? entering : leaving) += 1;
        (along < 0 ? entering_hits : leaving_hits) += want[i].hit ? 1 : 0;
    }
    EXPECT_GT(entering, static_cast<int>(rays.size() / 5));
    EXPECT_EQ(entering_hits, entering) << "rays into a closed solid must hit it";
    EXPECT_GT(leaving, static_cast<int>(rays.size() / 5));
    EXPECT_EQ(leaving_hits, 0) << "rays leaving a convex solid must miss it";
}

constexpr int kRaysPerScene = 3000;

TEST(RaysFromPolygons, EveryMethodGivesBruteForceAnswers) {
    for (const SceneCase& c : scene_cases()) {
        SCOPED_TRACE(c.name);
        const std::vector<SurfaceRay> rays = surface_rays(c.scene, kRaysPerScene, 41);
        const std::vector<Answer> want = answers_of(BruteForce(c.scene), rays);
        EXPECT_GE(hits_in(want), c.minimum_hit_share * kRaysPerScene) << "too few hits";
        if (c.convex_closed) {
            expect_convex_solid_answers(c.scene, rays, want);
        }
        for (const Method& m : every_method(c.scene)) {
            SCOPED_TRACE(m.name);
            expect_answers(c.scene, *m.make(c.scene), rays, want, m.exact);
        }
    }
}

TEST(RaysFromPolygons, EveryMethodSkipsThePolygonARayLeaves) {
    for (const SceneCase& c : scene_cases()) {
        SCOPED_TRACE(c.name);
        const std::vector<SurfaceRay> rays = grazing_surface_rays(c.scene, 1500, 43);
        const BruteForce brute(c.scene);
        TraceCounters counters;
        int given_back = 0;  // the premise: without Ray::leaves, the polygon comes back
        for (const SurfaceRay& r : rays) {
            Ray plain = r.ray;
            plain.leaves = kLeavesNoPolygon;
            const std::optional<Hit> hit = brute.closest_hit(plain, r.t, counters);
            given_back += hit && hit->polygon == r.from ? 1 : 0;
        }
        EXPECT_GT(given_back, 100);
        const std::vector<Answer> want = answers_of(brute, rays);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            ASSERT_FALSE(want[i].hit && want[i].hit->polygon == rays[i].from);
        }
        for (const Method& m : every_method(c.scene)) {
            SCOPED_TRACE(m.name);
            expect_answers(c.scene, *m.make(c.scene), rays, want, m.exact);
        }
    }
}

// Polygons lying in the voxel method's own voxel faces (grid_test_support.h): rays from them
// start exactly on voxel boundaries, where the walk's first voxel and its near-hit rule are
// decided by rounding.
TEST(RaysFromPolygons, StartingInVoxelFacesGiveBruteForceAnswers) {
    const auto check = [](const Scene& scene, const Accelerator& accel, bool exact) {
        const std::vector<SurfaceRay> rays = surface_rays(scene, 2000, 45);
        const std::vector<Answer> want = answers_of(BruteForce(scene), rays);
        EXPECT_GE(hits_in(want), 400) << accel.name() << ": too few hits";
        expect_answers(scene, accel, rays, want, exact);
    };
    // Enough faces that a fifth of the rays from them meet another.
    const auto faces = [](int divisions) { return std::max(150, 3 * divisions * divisions); };
    for (const int side : {4, 9}) {
        Scene scene = unit_cube_anchors();
        const SeadsGrid bare = build_seads_grid(scene, side, false);
        add_lattice_faces(
            scene,
            [&bare](int axis, int k) { return bare.world.lo[axis] + k * bare.voxel_size[axis]; },
            side, faces(side), side);
        for (const bool near_hits : {false, true}) {
            const Seads accel(scene, settings(AccelKind::Seads, side, false, near_hits));
            ASSERT_EQ(accel.grid().world.lo, bare.world.lo);
            check(scene, accel, !near_hits);
        }
    }
    for (const int depth : {2, 4}) {
        Scene scene = unit_cube_anchors();
        OctreeBuildSettings build;
        build.depth = depth;
        const OctreeTree bare = build_octree_depth_first(scene, build);
        add_lattice_faces(
            scene, [&bare](int axis, int k) { return bare.lattice(axis, k); }, 1 << depth,
            faces(1 << depth), depth);
        for (const bool level_order : {false, true}) {
            for (const bool near_hits : {false, true}) {
                const Octree accel(scene,
                                   settings(AccelKind::Octree, depth, level_order, near_hits));
                ASSERT_EQ(accel.tree().world.lo, bare.world.lo);
                check(scene, accel, !near_hits);
            }
        }
    }
}

}  // namespace
}  // namespace rt::test
