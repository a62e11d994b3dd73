// Where reflected and refracted rays go: Snell's law with one index, a smoothed normal that would
// bend a ray to the wrong side (straightened unless -Ot), and a wide lobe near grazing that keeps
// its rays on the ray's side of the surface. Lamps placed where the rays must land tell.
#include <cmath>
#include <numbers>

#include "rt/accel/brute_force.h"
#include "rt/render/ray_tracer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

// The light one eye ray brings back.
Rgb trace_once(const Scene& scene, const ShadingSettings& settings, const Ray& ray) {
    const auto accel = make_brute_force(scene);
    const RayTracer tracer(scene, *accel, settings);
    SampleStream stream(settings.sampling.seed, 0, 0, 0);
    KindCounters counters;
    RayTreeCounts tree;
    SampleContext sample{stream, counters, tree, {}};
    return tracer.trace(ray, RayKind::Eye, 1, false, sample);
}

// A square of half side `half` in the plane z = centre.z, its outward normal along ±z.
void add_square(test::SceneBuilder& b, const Vec3& centre, double half, double normal_z,
                std::uint32_t attribute) {
    b.add_polygon({centre + Vec3{-half, -half, 0}, centre + Vec3{half, -half, 0},
                   centre + Vec3{half, half, 0}, centre + Vec3{-half, half, 0}},
                  {0, 0, normal_z}, attribute);
}

Attribute lamp() {
    Attribute a;
    a.color = {1, 1, 1};
    a.emission = 1.0;
    return a;
}

// Attribute 0 is the surface under test (a square in z = 0, outward normal -z), attribute 1 a lamp.
test::SceneBuilder surface_and_lamp(const Attribute& surface) {
    test::SceneBuilder b;
    b.scene().attributes = {surface, lamp()};
    b.scene().header.maxdepth = 2;
    add_square(b, {0, 0, 0}, 50.0, -1.0, 0);
    return b;
}

// Every vertex normal set to `normal`, and every polygon smooth-shaded.
void smooth_with(test::SceneBuilder& b, const Vec3& normal) {
    for (Vec3& n : b.scene().vertex_normals) {
        n = normal;
    }
    for (Polygon& p : b.scene().polygons) {
        p.smooth = true;
    }
}

ShadingSettings sharp_rays() {
    ShadingSettings settings;
    settings.attenuate_rays = false;
    settings.sampling.distribute = false;
    return settings;
}

Attribute glass() {
    Attribute a;
    a.color = {1, 1, 1};
    a.transmission = 1.0;
    a.refraction_index = {1.5, 1.5, 1.5};
    return a;
}

Attribute mirror() {
    Attribute a;
    a.color = {1, 1, 1};
    a.specular = 1.0;
    return a;
}

TEST(SecondaryRays, OneIndexBendsEveryChannelBySnellsLaw) {
    // 45 degrees onto glass of index 1.5: the ray crosses z = 10 at 10 tan(asin(sin 45 / 1.5)).
    const Ray ray{{-1, 0, -1}, normalize(Vec3{1, 0, 1})};
    const double bent = 10.0 * std::tan(std::asin(std::sin(radians(45)) / 1.5));
    test::SceneBuilder on_bent = surface_and_lamp(glass());
    add_square(on_bent, {bent, 0, 10}, 0.3, -1.0, 1);
    EXPECT_EQ(trace_once(on_bent.scene(), sharp_rays(), ray), (Rgb{1, 1, 1}));
    test::SceneBuilder on_unbent = surface_and_lamp(glass());
    add_square(on_unbent, {10, 0, 10}, 0.3, -1.0, 1);
    EXPECT_EQ(trace_once(on_unbent.scene(), sharp_rays(), ray), Rgb{});
}

TEST(SecondaryRays, SmoothingThatBendsTheMirrorRayInsideIsStraightenedUnlessDashOt) {
    // The shading normal leans 30 degrees toward +x: mirrored about it, the 45-degree ray would go
    // into the surface. Straightened, it leaves as the flat mirror sends it, to z = -10 at x = 10.
    const Ray ray{{-1, 0, -1}, normalize(Vec3{1, 0, 1})};
    test::SceneBuilder b = surface_and_lamp(mirror());
    smooth_with(b, {std::sin(radians(30)), 0, -std::cos(radians(30))});
    add_square(b, {10, 0, -10}, 0.5, 1.0, 1);
    EXPECT_EQ(trace_once(b.scene(), sharp_rays(), ray), (Rgb{1, 1, 1}));
    ShadingSettings dash_ot = sharp_rays();
    dash_ot.correct_smoothing = false;
    EXPECT_EQ(trace_once(b.scene(), dash_ot, ray), Rgb{});
}

TEST(SecondaryRays, SmoothingThatBendsTheRefractedRayBackIsStraightenedUnlessDashOt) {
    // From inside the glass (z > 0) at 70 degrees, the shading normal leaning 30 degrees back:
    // Snell's law would send the ray back into the glass. Straightened, it goes on along its own
    // line, to z = -5 at x = 5 tan 70.
    const Vec3 direction{std::sin(radians(70)), 0, -std::cos(radians(70))};
    const Ray ray{direction * -2.0, direction};
    test::SceneBuilder b = surface_and_lamp(glass());
    // Outward (-z side) vertex normals; seen from inside, the shading normal is their opposite.
    smooth_with(b, {std::sin(radians(30)), 0, -std::cos(radians(30))});
    add_square(b, {5 * std::tan(radians(70)), 0, -5}, 0.5, 1.0, 1);
    EXPECT_EQ(trace_once(b.scene(), sharp_rays(), ray), (Rgb{1, 1, 1}));
    ShadingSettings dash_ot = sharp_rays();
    dash_ot.correct_smoothing = false;
    EXPECT_EQ(trace_once(b.scene(), dash_ot, ray), Rgb{});
}

TEST(SecondaryRays, SmoothingThatSendsATotallyReflectedRayThroughIsMirroredUnlessDashOt) {
    // From inside the glass at 50 degrees, the shading normal leaning 25 degrees toward the ray's
    // way: 75 degrees from it, the ray is totally reflected, and mirrored about it would cross
    // the surface. Mirrored on the polygon instead, it stays inside, to z = 5 at x = 5 tan 50.
    const Vec3 direction{std::sin(radians(50)), 0, -std::cos(radians(50))};
    const Ray ray{direction * -2.0, direction};
    test::SceneBuilder b = surface_and_lamp(glass());
    // Outward (-z side) vertex normals; seen from inside, the shading normal is their opposite.
    smooth_with(b, {-std::sin(radians(25)), 0, -std::cos(radians(25))});
    add_square(b, {5 * std::tan(radians(50)), 0, 5}, 0.5, -1.0, 1);
    EXPECT_EQ(trace_once(b.scene(), sharp_rays(), ray), (Rgb{1, 1, 1}));
    ShadingSettings dash_ot = sharp_rays();
    dash_ot.correct_smoothing = false;
    EXPECT_EQ(trace_once(b.scene(), dash_ot, ray), Rgb{});
}

TEST(SecondaryRays, AMappedNormalIsCorrectedLikeASmoothedOne) {
    // -V: a sphere of radius 1.2 centred on the origin in the mirror's plane tilts the normal at
    // x = 1 by asin(1/1.2), 56 degrees toward +x: the 45-degree ray mirrored about it would go
    // into the surface. As with smoothing, it leaves as the flat mirror sends it.
    const Ray ray{{0, 0, -1}, normalize(Vec3{1, 0, 1})};  // meets the mirror at x = 1
    test::SceneBuilder b = surface_and_lamp(mirror());
    TextureCell cell;
    cell.tangent_u = {1, 0, 0};
    cell.tangent_v = {0, -1, 0};  // u x v = -z, the square's outward side
    cell.across_axis = cell.tangent_v;
    cell.optical_centre = {0, 0, 0};
    cell.sphere = 1.0 / 1.2;
    b.scene().texture_cells = {cell};
    b.scene().texture_grids = {TextureGrid{1, 1}};
    b.scene().polygons[0].texture_cell = 0;
    add_square(b, {11, 0, -10}, 0.5, 1.0, 1);  // where the flat mirror sends it
    EXPECT_EQ(trace_once(b.scene(), sharp_rays(), ray), (Rgb{1, 1, 1}));
    ShadingSettings dash_ot = sharp_rays();
    dash_ot.correct_smoothing = false;
    EXPECT_EQ(trace_once(b.scene(), dash_ot, ray), Rgb{});
}

// A glossy mirror with a 60-degree lobe, hit 80 degrees from its normal: much of the lobe lies
// beyond the surface, and those rays are turned back to the ray's side, so that a lamp filling
// the ray's side receives every ray and one behind the mirror none.
TEST(SecondaryRays, AWideLobeNearGrazingKeepsItsRaysOnTheRaysSide) {
    Attribute glossy = mirror();
    glossy.reflect_cone_degrees = 60.0;
    const Vec3 direction{std::sin(radians(80)), 0, std::cos(radians(80))};
    const Ray ray{direction * -2.0, direction};
    ShadingSettings settings;
    settings.attenuate_rays = false;
    settings.sampling.adaptive = false;
    for (const double lamp_z : {-5.0, 5.0}) {
        test::SceneBuilder b = surface_and_lamp(glossy);
        b.scene().header.maxdist = 1;
        b.scene().view.sample_resolution_x = 4;
        b.scene().view.sample_resolution_y = 4;
        add_square(b, {0, 0, lamp_z}, 1e4, -lamp_z, 1);
        const Rgb got = trace_once(b.scene(), settings, ray);
        EXPECT_NEAR(got.g, lamp_z < 0 ? 1.0 : 0.0, 1e-12) << "lamp at z = " << lamp_z;
    }
}

}  // namespace
}  // namespace rt
