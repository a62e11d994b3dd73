// Polygons between the eye and the screen, which eye rays starting on the screen do not see.
#include "rt/scene/near_plane.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// The builder's eye is at (0, 0, -10) looking at the origin along +z, with 30-degree angles.
Scene square_at(double z, double x_centre = 0.0, double screendist = 1.0) {
    test::SceneBuilder b;
    b.add_polygon(
        {{x_centre - 1, -1, z}, {x_centre + 1, -1, z}, {x_centre + 1, 1, z}, {x_centre - 1, 1, z}},
        {0, 0, -1});
    b.scene().view.screen_distance = screendist;
    return b.scene();
}

TEST(NearPlane, ASquareBeyondTheScreenIsNotCounted) {
    EXPECT_EQ(polygons_before_screen(square_at(0.0)).polygons, 0u);
}

TEST(NearPlane, ASquareBeforeTheScreenIsCountedWithItsDepth) {
    const NearPlaneReport r = polygons_before_screen(square_at(0.0, 0.0, 12.0));
    EXPECT_EQ(r.polygons, 1u);
    EXPECT_NEAR(r.nearest_depth, 10.0, 1e-12);
    EXPECT_NEAR(screendist_showing(r), 9.9, 1e-12);
    EXPECT_LT(screendist_showing(r), r.nearest_depth);
}

TEST(NearPlane, ASquareOutsideTheViewIsNotCounted) {
    // At depth 10 the view reaches 10 tan 15 = 2.7 to the side; the square spans x 99 to 101.
    EXPECT_EQ(polygons_before_screen(square_at(0.0, 100.0, 12.0)).polygons, 0u);
}

TEST(NearPlane, ASquareOnTheScreenItselfIsSeen) {
    EXPECT_EQ(polygons_before_screen(square_at(0.0, 0.0, 10.0)).polygons, 0u);
}

TEST(NearPlane, OnlyThePartInViewSetsTheNearestDepth) {
    // A floor strip from depth 2 to depth 30 below the eye: at depth 2 it is out of view (the
    // view reaches 2 tan 15 = 0.54 down there), so the nearest part seen is where y = -1 enters
    // the pyramid, at depth 1 / tan 15 = 3.73.
    test::SceneBuilder b;
    b.add_polygon({{-1, -1, -8}, {1, -1, -8}, {1, -1, 20}, {-1, -1, 20}}, {0, 1, 0});
    b.scene().view.screen_distance = 12.0;
    const NearPlaneReport r = polygons_before_screen(b.scene());
    EXPECT_EQ(r.polygons, 1u);
    EXPECT_NEAR(r.nearest_depth, 1.0 / std::tan(std::numbers::pi / 12.0), 1e-9);
}

TEST(NearPlane, APolygonThroughTheEyeHasNoScreendistThatShowsIt) {
    test::SceneBuilder b;
    // In the plane y = 0, around the eye (0, 0, -10): its part in view starts at the eye.
    b.add_polygon({{-1, 0, -11}, {1, 0, -11}, {0, 0, 5}}, {});
    b.add_polygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}}, {0, 0, -1});
    b.scene().view.screen_distance = 12.0;
    const NearPlaneReport r = polygons_before_screen(b.scene());
    EXPECT_EQ(r.polygons, 2u);
    EXPECT_EQ(screendist_showing(r), 0.0);
}

}  // namespace
}  // namespace rt
