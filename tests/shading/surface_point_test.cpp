// describe_hit: which normal the illumination model shades with (the polygon's, a -M shape's, the
// interpolated vertex normals) and on which side, against normals worked out by hand.
#include "rt/shading/surface_point.h"

#include <cmath>

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

void expect_near(const Vec3& got, const Vec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

// The unit square in z = 0 with its normal along +z; the ray comes down onto (x, y, 0).
struct Square {
    Square() { builder.add_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1}); }
    SurfacePoint hit_at(double x, double y, bool from_front, const ShadingSettings& settings = {}) {
        const double side = from_front ? 1.0 : -1.0;
        const Ray ray{{x, y, 3.0 * side}, {0, 0, -side}};
        return describe_hit(builder.scene(), settings, ray, Hit{3.0, 0});
    }
    test::SceneBuilder builder;
};

TEST(SurfacePoint, FlatPolygonShadesWithItsOwnNormalTurnedToTheRay) {
    Square square;
    const SurfacePoint front = square.hit_at(0.3, 0.6, true);
    EXPECT_TRUE(front.front);
    expect_near(front.position, {0.3, 0.6, 0.0});
    expect_near(front.facing_normal, {0, 0, 1});
    expect_near(front.shading_normal, {0, 0, 1});
    const SurfacePoint back = square.hit_at(0.3, 0.6, false);
    EXPECT_FALSE(back.front);
    expect_near(back.facing_normal, {0, 0, -1});
    expect_near(back.shading_normal, {0, 0, -1});
}

TEST(SurfacePoint, SphereMarkShadesWithTheRadiusThroughThePoint) {
    // -M mark 2: the square is a facet of the sphere of centre (0.5, 0.5, -2).
    Square square;
    Scene& scene = square.builder.scene();
    scene.shapes.push_back(Shape{{0.5, 0.5, -2.0}, 2.0, {}, 1, {}});
    scene.polygons[0].mark = PolygonMark::Sphere;
    scene.polygons[0].shape = 0;
    const Vec3 radial = normalize(Vec3{0.9, 0.2, 0.0} - Vec3{0.5, 0.5, -2.0});
    expect_near(square.hit_at(0.9, 0.2, true).shading_normal, radial);
    expect_near(square.hit_at(0.9, 0.2, false).shading_normal, -radial);
    // The geometric normal is still the polygon's.
    expect_near(square.hit_at(0.9, 0.2, true).facing_normal, {0, 0, 1});
}

TEST(SurfacePoint, MarkOneInterpolatesTheVertexNormals) {
    // Vertex normals tilted toward +x along the x = 1 edge: halfway across, the mean value
    // coordinates weigh both edges equally.
    Square square;
    Scene& scene = square.builder.scene();
    const Vec3 up{0, 0, 1};
    const Vec3 tilted = normalize(Vec3{1, 0, 1});
    scene.vertex_normals = {up, tilted, tilted, up};  // corners (0,0) (1,0) (1,1) (0,1)
    scene.polygons[0].mark = PolygonMark::InterpolatesNormals;
    scene.polygons[0].smooth = true;
    expect_near(square.hit_at(0.5, 0.5, true).shading_normal, normalize((up + tilted) * 0.5));
    expect_near(square.hit_at(1.0, 0.5, true).shading_normal, tilted);
    expect_near(square.hit_at(0.5, 0.5, false).shading_normal, -normalize(up + tilted));
}

TEST(SurfacePoint, NormalLeaningAwayFromTheRayIsStraightenedUnlessDashOt) {
    // Vertex normals pointing below the polygon's plane on the viewer's side.
    Square square;
    Scene& scene = square.builder.scene();
    const Vec3 under = normalize(Vec3{1, 0, -0.5});
    scene.vertex_normals = {under, under, under, under};
    scene.polygons[0].smooth = true;
    expect_near(square.hit_at(0.5, 0.5, true).shading_normal, {0, 0, 1});
    ShadingSettings dash_ot;
    dash_ot.correct_smoothing = false;
    expect_near(square.hit_at(0.5, 0.5, true, dash_ot).shading_normal, under);
}

TEST(SurfacePoint, DashPoMakesSmoothPolygonsOpaque) {
    Square square;
    Scene& scene = square.builder.scene();
    scene.attributes[0].transmission = 0.4;
    EXPECT_EQ(square.hit_at(0.5, 0.5, true).transmission, 0.4);
    square.builder.smooth_vertex_normals();
    EXPECT_EQ(square.hit_at(0.5, 0.5, true).transmission, 0.4);
    ShadingSettings dash_po;
    dash_po.smooth_shaded_opaque = true;
    EXPECT_EQ(square.hit_at(0.5, 0.5, true, dash_po).transmission, 0.0);
}

// -V: a texture cell on the square, a sphere of radius 1 centred on (0.5, 0.5) in its plane, and
// a colour that tints the attribute's.
TextureCell sphere_cell() {
    TextureCell cell;
    cell.tangent_u = {1, 0, 0};
    cell.tangent_v = {0, 1, 0};
    cell.across_axis = {0, 1, 0};
    cell.optical_centre = {0.5, 0.5, 0};
    cell.sphere = 1.0;
    cell.color = {0.5, 1.0, 0.25};
    return cell;
}

TEST(SurfacePoint, ATextureCellGivesTheNormalAndTintsTheColour) {
    Square square;
    Scene& scene = square.builder.scene();
    scene.attributes[0].color = {0.8, 0.6, 0.4};
    EXPECT_EQ(square.hit_at(0.5, 0.5, true).color, (Rgb{0.8, 0.6, 0.4}));
    scene.texture_cells = {sphere_cell()};
    scene.texture_grids = {TextureGrid{1, 1}};
    scene.polygons[0].texture_cell = 0;
    // Half the radius away from the centre along x: the sphere's normal there, tilted asin(1/2).
    const Vec3 sphere_normal{0.5, 0, std::sqrt(0.75)};
    const SurfacePoint front = square.hit_at(1.0, 0.5, true);
    expect_near(front.shading_normal, sphere_normal);
    expect_near(front.facing_normal, {0, 0, 1});
    EXPECT_EQ(front.color, (Rgb{0.4, 0.6, 0.1}));
    // From behind, the same normal turned to the ray.
    expect_near(square.hit_at(1.0, 0.5, false).shading_normal, -sphere_normal);
    // -Po makes smooth polygons opaque; a texture-mapped one is not smooth.
    scene.attributes[0].transmission = 0.4;
    ShadingSettings dash_po;
    dash_po.smooth_shaded_opaque = true;
    EXPECT_EQ(square.hit_at(1.0, 0.5, true, dash_po).transmission, 0.4);
}

}  // namespace
}  // namespace rt
