// The stack's exit culling layer: built unless -De, or unless the scene has more polygons than
// the render has rays from the eye for its table to cull (then -p says why); -de keeps it.
#include "rt/accel/accelerator_stack.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// A box of six squares, brute force beneath.
Scene box() {
    return test::make_box({-1, -1, -1}, {1, 1, 1}, false);
}

AcceleratorStackSettings brute_with_eye_rays(std::uint64_t eye_rays) {
    AcceleratorStackSettings s;
    s.method.kind = AccelKind::BruteForce;
    s.most_eye_rays = eye_rays;
    return s;
}

bool says_off(const std::vector<std::string>& lines) {
    return !lines.empty() && lines.front().starts_with("exit culling: off (");
}

TEST(ExitCullingLeftOut, WhenThePolygonsOutnumberTheEyeRays) {
    const Scene scene = box();
    ASSERT_EQ(scene.polygons.size(), 6u);
    EXPECT_EQ(exit_culling_left_out(scene, brute_with_eye_rays(5)),
              "6 polygons, more than the 5 rays from the eye it could cull; -de keeps it");
    EXPECT_EQ(exit_culling_left_out(scene, brute_with_eye_rays(6)), "");
    EXPECT_EQ(exit_culling_left_out(scene, brute_with_eye_rays(0)), "");  // not known: kept
}

TEST(ExitCullingLeftOut, NotWhenSwitchedOffOrChecked) {
    const Scene scene = box();
    AcceleratorStackSettings off = brute_with_eye_rays(1);
    off.exit_culling = false;  // -De: off, but not left out by the stack's own choice
    EXPECT_EQ(exit_culling_left_out(scene, off), "");
    AcceleratorStackSettings checked = brute_with_eye_rays(1);
    checked.check_exit_culling = true;  // -de asks for the layer, to check it
    EXPECT_EQ(exit_culling_left_out(scene, checked), "");
}

TEST(AcceleratorStack, LeavesExitCullingOutAndSaysSo) {
    const Scene scene = box();
    const AcceleratorStack few(scene, brute_with_eye_rays(5), {});
    EXPECT_EQ(few.top().name(), "brute force");
    EXPECT_TRUE(says_off(few.report_lines()));

    const AcceleratorStack enough(scene, brute_with_eye_rays(6), {});
    EXPECT_EQ(enough.top().name(), "exit culling over brute force");
    EXPECT_FALSE(says_off(enough.report_lines()));

    AcceleratorStackSettings checked = brute_with_eye_rays(5);
    checked.check_exit_culling = true;
    const AcceleratorStack kept(scene, checked, {});
    EXPECT_EQ(kept.top().name(), "exit culling over brute force");

    AcceleratorStackSettings off = brute_with_eye_rays(5);
    off.exit_culling = false;
    const AcceleratorStack switched_off(scene, off, {});
    EXPECT_EQ(switched_off.top().name(), "brute force");
    EXPECT_FALSE(says_off(switched_off.report_lines()));  // -De says nothing
}

}  // namespace
}  // namespace rt
