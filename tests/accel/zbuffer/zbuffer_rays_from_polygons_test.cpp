// The z-buffer (--zbuffer) answers the eye rays the renderer asks through its eye-ray entry point
// from its item buffer, and sends every other ray to the method below it. Some rays here are
// eye rays that start on polygons (where polygons cross the screen); asked as eye rays, the buffer
// answers them exactly. The same points in other directions, asked as eye rays, are not of the
// buffer's view and go below; rays asked as any ray always go below.
#include <memory>
#include <random>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/bvh/bvh.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/accel/zbuffer/zbuffer_first_hits.h"
#include "rt/geometry/camera.h"

#include <gtest/gtest.h>

#include "accel/surface_rays.h"
#include "support/scene_builder.h"

namespace rt::test {
namespace {

// Passes every query on and counts the nearest-hit ones, to show which rays the z-buffer answered
// itself (occlusion always goes below).
class Counting : public Accelerator {
public:
    explicit Counting(std::unique_ptr<Accelerator> inner) : inner_(std::move(inner)) {}
    std::string_view name() const override { return inner_->name(); }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override {
        ++calls;
        return inner_->closest_hit(ray, t, counters);
    }
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return inner_->occluded(ray, t, counters);
    }
    mutable int calls = 0;

private:
    std::unique_ptr<Accelerator> inner_;
};

// A closed box around a tube along z whose walls are cut into quads at z = -1, 0, 1, with the eye
// inside the tube and the screen at z = 0: the tube's walls cross the screen on their shared
// edges, so a ray from such a point away from the eye is an eye ray that starts on polygons.
Scene tube_in_a_box() {
    SceneBuilder b;
    const Scene outer = make_box({-3, -3, -3}, {3, 3, 3}, false);
    for (const Polygon& p : outer.polygons) {
        std::vector<Vec3> loop;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            loop.push_back(outer.corner_position(p, k));
        }
        b.add_polygon(loop, p.normal);
    }
    for (double z = -2; z < 2; z += 1) {
        b.add_polygon({{1, -1, z}, {1, 1, z}, {1, 1, z + 1}, {1, -1, z + 1}}, {1, 0, 0});
        b.add_polygon({{-1, -1, z}, {-1, -1, z + 1}, {-1, 1, z + 1}, {-1, 1, z}}, {-1, 0, 0});
        b.add_polygon({{-1, 1, z}, {-1, 1, z + 1}, {1, 1, z + 1}, {1, 1, z}}, {0, 1, 0});
        b.add_polygon({{-1, -1, z}, {1, -1, z}, {1, -1, z + 1}, {-1, -1, z + 1}}, {0, -1, 0});
    }
    Scene scene = std::move(b.scene());
    scene.view.eye = {0.1, -0.2, -0.625};
    scene.view.look = {0.1, -0.2, 1.0};
    scene.view.screen_distance = 0.625;  // the screen at z = 0 exactly
    scene.view.view_angle_x_degrees = 140.0;
    scene.view.view_angle_y_degrees = 140.0;
    scene.view.width = 40;
    scene.view.height = 40;
    return scene;
}

// The renderer's full stack, z-buffer over exit culling over the BVH, on eye rays that start on
// the tube's walls, eye rays from the screen, and rays from polygons anywhere.
TEST(ZBufferRaysFromPolygons, ZBufferOverExitCullingGivesBruteForceAnswers) {
    const Scene scene = tube_in_a_box();
    const Camera view = scene.view.camera();
    const Counting below(std::make_unique<ExitCulling>(scene, make_bvh(scene)));
    const auto zbuffer = make_zbuffer_first_hits(scene, view, below);
    ASSERT_TRUE(zbuffer->statistics().active) << zbuffer->statistics().inactive_reason;
    const double epsilon = renderer_epsilon(scene);
    std::mt19937_64 rng(43);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<SurfaceRay> on_walls;
    for (int i = 0; i < 800; ++i) {
        const double along = 2 * unit(rng) - 1;
        const double side = i % 2 == 0 ? 1.0 : -1.0;
        const Vec3 origin = i % 4 < 2 ? Vec3{side, along, 0.0} : Vec3{along, side, 0.0};
        on_walls.push_back(
            {{origin, normalize(origin - scene.view.eye)}, {epsilon, kBeyondAnyScene}});
    }
    const BruteForce brute(scene);
    // Compares with brute force; returns brute force's hits.
    const auto expect_brute_answers = [&](const std::vector<SurfaceRay>& rays, AskedAs asked) {
        const std::vector<Answer> want = answers_of(brute, rays);
        expect_answers(scene, *zbuffer, rays, want, true, asked);
        return hits_in(want);
    };
    // Every ray from the tube's walls away from the eye meets the closed outer box, and the
    // item buffer answers each (not the fallback).
    const int n = static_cast<int>(on_walls.size());
    EXPECT_EQ(expect_brute_answers(on_walls, AskedAs::EyeRay), n);
    EXPECT_EQ(below.calls, 0);
    std::vector<SurfaceRay> from_screen;
    for (int i = 0; i < 800; ++i) {
        from_screen.push_back({view.primary_ray(unit(rng) * view.width, unit(rng) * view.height),
                               {epsilon, kBeyondAnyScene}});
    }
    EXPECT_EQ(expect_brute_answers(from_screen, AskedAs::EyeRay),
              static_cast<int>(from_screen.size()));
    EXPECT_EQ(below.calls, 0);
    // The same eye rays asked as any ray: the fallback's to answer.
    EXPECT_EQ(expect_brute_answers(on_walls, AskedAs::AnyRay), n);
    EXPECT_EQ(below.calls, n);
    // From the same points in other directions: not rays of the buffer's view, so asked as eye
    // rays they go to the fallback all the same.
    std::vector<SurfaceRay> turned = on_walls;
    for (SurfaceRay& r : turned) {
        r.ray.direction = random_direction(rng);
    }
    int calls = below.calls;
    EXPECT_GE(expect_brute_answers(turned, AskedAs::EyeRay), 300);
    EXPECT_EQ(below.calls - calls, n);
    calls = below.calls;
    const std::vector<SurfaceRay> anywhere = surface_rays(scene, 3000, 44);
    EXPECT_GE(expect_brute_answers(anywhere, AskedAs::AnyRay), 1500);
    EXPECT_EQ(below.calls - calls, static_cast<int>(anywhere.size()))
        << "rays from polygons go to the fallback";
}

}  // namespace
}  // namespace rt::test
