// Exit culling answers rays itself (from their guards, from the eye rays' item buffer) only where
// the method would give brute force's answer: with a switch that makes the method answer
// otherwise on purpose (-on, -of, -tv), or a debugging layer watching it (-ds, -dl), every ray the
// layer does not cull goes to the method.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "rt/accel/accelerator_stack.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"
#include "accel/surface_rays.h"

namespace rt::test {
namespace {

// Rays answered by the layer itself, of the view's eye rays and of rays leaving each polygon
// towards points of the others (reflected rays, feelers), through the stack's top.
std::uint64_t answered(const Scene& scene, const AcceleratorStackSettings& settings) {
    const AcceleratorStack stack(scene, settings, AccelMessages{});
    const Accelerator& top = stack.top();
    TraceCounters counters;
    const Camera view = scene.view.camera();
    for (int y = 0; y < view.height; y += 9) {
        for (int x = 0; x < view.width; x += 9) {
            top.eye_ray_closest_hit(view.primary_ray(x + 0.5, y + 0.5), {1e-9, kBeyondAnyScene},
                                    counters);
        }
    }
    std::mt19937_64 rng(15);
    const auto count = static_cast<std::uint32_t>(scene.polygons.size());
    const double epsilon = renderer_epsilon(scene);
    for (std::uint32_t from = 0; from < count; ++from) {
        for (std::uint32_t to = 0; to < count; ++to) {
            Ray ray{point_on(scene, from, rng), {}, from};
            ray.direction = point_on(scene, to, rng) - ray.origin;
            if (to != from) {
                top.closest_hit(ray, {epsilon, kBeyondAnyScene}, counters);
            }
        }
    }
    return counters.guard_answers;
}

TEST(ExitCullingAnswers, OnlyWhereTheMethodGivesBruteForcesAnswers) {
    const Scene scene = load_twocubes();
    const AcceleratorStackSettings plain;
    EXPECT_GT(answered(scene, plain), 100u);
    const std::vector<std::pair<std::string, std::function<void(AcceleratorStackSettings&)>>>
        otherwise{
            {"-on", [](AcceleratorStackSettings& s) { s.method.accept_near_hits = true; }},
            {"-of", [](AcceleratorStackSettings& s) { s.method.no_fudge = true; }},
            {"-tv 1", [](AcceleratorStackSettings& s) { s.method.terminate_after_voxels = 1; }},
            {"-ds", [](AcceleratorStackSettings& s) { s.strike_check = true; }},
            {"-dsp", [](AcceleratorStackSettings& s) { s.strike_print = true; }},
            {"-dl", [](AcceleratorStackSettings& s) { s.log_intersections = true; }},
        };
    for (const auto& [name, set] : otherwise) {
        AcceleratorStackSettings settings;
        set(settings);
        EXPECT_EQ(answered(scene, settings), 0u) << name;
    }
}

// With --zbuffer the z-buffer above answers the eye rays first: exit culling keeps no item buffer.
TEST(ExitCullingAnswers, NoItemBufferUnderTheZBuffer) {
    const Scene scene = load_twocubes();
    const auto mentions_item_buffer = [&](const AcceleratorStackSettings& settings) {
        const AcceleratorStack stack(scene, settings, AccelMessages{});
        const std::vector<std::string> lines = stack.report_lines();
        return std::any_of(lines.begin(), lines.end(), [](const std::string& line) {
            return line.find("item buffer") != std::string::npos;
        });
    };
    EXPECT_TRUE(mentions_item_buffer({}));
    AcceleratorStackSettings zbuffer;
    zbuffer.zbuffer_first_hits = true;
    EXPECT_FALSE(mentions_item_buffer(zbuffer));
}

}  // namespace
}  // namespace rt::test
