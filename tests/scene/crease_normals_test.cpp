// -E: smooth shading keeps creases sharper than the angle.
#include "rt/scene/crease_normals.h"

#include <numbers>

#include "rt/geometry/normals.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

TEST(CreaseNormals, ABoxKeepsItsEdgesBelowTheAngleAndRoundsThemAbove) {
    test::SceneBuilder b;
    b.scene() = test::make_box({0, 0, 0}, {1, 1, 1}, false);
    test::SceneBuilder smooth;
    smooth.scene() = b.scene();
    smooth.smooth_vertex_normals();
    Scene scene = smooth.scene();
    const Vec3 near_corner{0.99, 0.99, 1.0};  // on the top face (z = 1), near a corner
    std::uint32_t top = 0;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        if (scene.polygons[id].normal.z > 0.9) {
            top = id;
        }
    }
    // Plain smooth shading: the corner's normal leans toward the diagonal.
    EXPECT_LT(interpolated_normal(scene.polygon_view(top), scene.normals_of(top), near_corner).z,
              0.9);
    // -E below 90 degrees: every corner of the top face keeps the face's normal.
    compute_crease_normals(scene, std::numbers::pi / 4);
    const Vec3 sharp =
        interpolated_normal(scene.polygon_view(top), scene.normals_of(top), near_corner);
    EXPECT_NEAR(sharp.z, 1.0, 1e-12);
    // -E above 90 degrees: the neighbours count again, as without -E.
    compute_crease_normals(scene, std::numbers::pi * 0.6);
    EXPECT_LT(interpolated_normal(scene.polygon_view(top), scene.normals_of(top), near_corner).z,
              0.9);
}

}  // namespace
}  // namespace rt
