// The wireframe's projection is the renderer's camera run backwards: a point on an eye ray lands
// where that ray leaves the pixel grid, lines are cut at the screen (where eye rays start) and at
// the view area's edges.
#include "rt/wireframe/line_projection.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

namespace rt {
namespace {

Camera test_camera() {
    CameraPlacement placement;
    placement.eye = {1.0, 2.0, -10.0};
    placement.look = {0.0, 0.0, 0.0};
    placement.screen_distance = 2.0;
    placement.view_angle_x_degrees = 40.0;
    placement.view_angle_y_degrees = 30.0;
    placement.width = 64;
    placement.height = 48;
    return Camera::placed(placement);
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - (a + ab * t));
}

TEST(LineProjection, APointOnAnEyeRayLandsWhereTheRayWasSent) {
    const Camera camera = test_camera();
    const LineProjection projection(camera);
    for (double px = 0.0; px <= 64.0; px += 7.3) {
        for (double py = 0.0; py <= 48.0; py += 5.9) {
            const Ray ray = camera.primary_ray(px, py);
            for (const double t : {0.0, 0.5, 3.0, 40.0}) {
                const std::optional<PixelPoint> p = projection.point(ray.at(t));
                ASSERT_TRUE(p.has_value());
                EXPECT_NEAR(p->x, px, 1e-9);
                EXPECT_NEAR(p->y, py, 1e-9);
            }
        }
    }
}

TEST(LineProjection, NothingNearerThanTheScreenIsSeen) {
    const Camera camera = test_camera();
    const LineProjection projection(camera);
    const Vec3 behind_eye = camera.eye - camera.forward * 3.0;
    const Vec3 before_screen = camera.eye + camera.forward * 1.5;  // the screen is at 2
    const Vec3 far_away = camera.eye + camera.forward * 30.0 + camera.right * 2.0;
    EXPECT_FALSE(projection.point(behind_eye).has_value());
    EXPECT_FALSE(projection.point(before_screen).has_value());
    EXPECT_FALSE(projection.segment(behind_eye, before_screen).has_value());
    // A line from behind the eye is seen from where it crosses the screen: the eye ray through
    // its near end starts on the line.
    for (const Vec3& near : {behind_eye, before_screen}) {
        const std::optional<PixelSegment> s = projection.segment(near, far_away);
        ASSERT_TRUE(s.has_value());
        const Ray ray = camera.primary_ray(s->from.x, s->from.y);
        EXPECT_LT(distance_to_segment(ray.origin, near, far_away), 1e-9);
        const std::optional<PixelPoint> end = projection.point(far_away);
        ASSERT_TRUE(end.has_value());
        EXPECT_NEAR(s->to.x, end->x, 1e-9);
        EXPECT_NEAR(s->to.y, end->y, 1e-9);
    }
}

TEST(LineProjection, LinesAreCutAtTheViewsEdges) {
    const Camera camera = test_camera();  // 64 x 48 pixels
    const LineProjection projection(camera);
    // Across the whole view and beyond, left to right along row 17.
    const Ray left = camera.primary_ray(-20.0, 17.0);
    const Ray right = camera.primary_ray(90.0, 17.0);
    const std::optional<PixelSegment> s = projection.segment(left.at(10.0), right.at(10.0));
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(std::min(s->from.x, s->to.x), 0.0, 1e-9);
    EXPECT_NEAR(std::max(s->from.x, s->to.x), 64.0, 1e-9);  // the last column ends at 64
    EXPECT_NEAR(s->from.y, 17.0, 1e-9);
    EXPECT_NEAR(s->to.y, 17.0, 1e-9);
    // Below the view: nothing; inside it: untouched.
    const Ray low_a = camera.primary_ray(12.0, 50.0);
    const Ray low_b = camera.primary_ray(40.0, 60.0);
    EXPECT_FALSE(projection.segment(low_a.at(5.0), low_b.at(5.0)).has_value());
    const Ray in_a = camera.primary_ray(12.5, 6.25);
    const Ray in_b = camera.primary_ray(48.0, 29.5);
    const std::optional<PixelSegment> inside = projection.segment(in_a.at(1.0), in_b.at(7.0));
    ASSERT_TRUE(inside.has_value());
    EXPECT_NEAR(inside->from.x, 12.5, 1e-9);
    EXPECT_NEAR(inside->from.y, 6.25, 1e-9);
    EXPECT_NEAR(inside->to.x, 48.0, 1e-9);
    EXPECT_NEAR(inside->to.y, 29.5, 1e-9);
}

}  // namespace
}  // namespace rt
