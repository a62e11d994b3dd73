// The most rays a render sends from the eye, against what renders send: the bound exit culling's
// choice rests on (AcceleratorStackSettings::most_eye_rays).
#include <algorithm>
#include <cstdint>

#include "rt/accel/brute_force.h"
#include "rt/render/renderer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// Keeps, over every pixel, the most samples and centre probes one pixel took.
class MostPerPixel : public RenderObserver {
public:
    bool wants_sample_reports() const override { return true; }
    void pixel_sampled(int /*x*/, int /*y*/, const PixelReport& report) override {
        most = std::max<std::uint64_t>(most, std::uint64_t{report.samples} + report.probes);
        samples = std::max<std::uint64_t>(samples, report.samples);
    }
    std::uint64_t most = 0;
    std::uint64_t samples = 0;
};

// A box seen across its edges, so that the adaptive rule meets pixels that see one surface (and
// probe their neighbours) and pixels that see two (and take every sample).
Scene box_scene(int resolution) {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, false);
    scene.view.look = {0, 0, 0};
    scene.view.sample_resolution_x = resolution;
    scene.view.sample_resolution_y = resolution;
    return scene;
}

struct Rendered {
    RenderStatistics statistics;
    std::uint64_t most_per_pixel = 0;
    std::uint64_t most_samples = 0;
};

Rendered render_box(const Scene& scene, const RenderSettings& settings) {
    const BruteForce accel(scene);
    MostPerPixel observer;
    Rendered out;
    (void)render(scene, accel, settings, observer, out.statistics);
    out.most_per_pixel = observer.most;
    out.most_samples = observer.samples;
    return out;
}

TEST(MostEyeRays, IsOnePerPixelAtASampleResolutionOfOne) {
    const Scene scene = box_scene(1);
    RenderSettings settings;
    settings.window = {0, 0, 11, 8};
    EXPECT_EQ(most_eye_rays(scene, settings), 12u * 9u);
    const Rendered r = render_box(scene, settings);
    EXPECT_EQ(r.statistics.by_kind[RayKind::Eye].rays, 12u * 9u);
    EXPECT_EQ(r.most_per_pixel, 1u);  // one sample, and no neighbour is asked
}

TEST(MostEyeRays, BoundsEveryPixelsSamplesAndProbes) {
    for (const int resolution : {2, 3, 4}) {
        for (const bool adaptive : {true, false}) {
            SCOPED_TRACE(::testing::Message()
                         << "resolution " << resolution << (adaptive ? ", adaptive" : ", -Dx"));
            const Scene scene = box_scene(resolution);
            RenderSettings settings;
            settings.window = {2, 3, 17, 14};
            settings.shading.sampling.adaptive = adaptive;
            const std::uint64_t pixels = std::uint64_t{16} * 12;
            const std::uint64_t per_pixel = most_eye_rays(scene, settings) / pixels;
            EXPECT_EQ(most_eye_rays(scene, settings) % pixels, 0u);
            const Rendered r = render_box(scene, settings);
            EXPECT_LE(r.most_per_pixel, per_pixel);
            EXPECT_EQ(r.most_samples, static_cast<std::uint64_t>(resolution * resolution));
            EXPECT_LE(r.statistics.by_kind[RayKind::Eye].rays, most_eye_rays(scene, settings));
        }
    }
}

TEST(MostEyeRays, IsNoneForAnEmptyWindow) {
    const Scene scene = box_scene(3);
    RenderSettings settings;
    settings.window = {5, 5, 4, 5};  // right of its left edge: no pixel
    EXPECT_EQ(most_eye_rays(scene, settings), 0u);
}

}  // namespace
}  // namespace rt
