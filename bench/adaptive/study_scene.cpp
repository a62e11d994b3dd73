#include "study_scene.h"

#include <iostream>

#include "rt/app/run.h"
#include "rt/app/run_settings.h"
#include "rt/render/film_window.h"
#include "rt/scene/read/load_scene.h"

namespace rt::bench {

StudyScene::StudyScene(const Options& options, const std::optional<PixelRect>& window) {
    RunConsole console;
    console.warning = [](const std::string& m) {
        std::cerr << "rt_adaptive_study: warning: " << m << '\n';
    };
    console.note = [](const std::string& m) { std::cerr << "rt_adaptive_study: " << m << '\n'; };
    Diagnostics diagnostics;
    diagnostics.set_warning_sink(console.warning);
    scene_ = load_scene(resolve_scene_path(options.scene), options.dialect, diagnostics);
    settings_.shading = run_shading(options);
    prepare_scene(scene_, options, settings_.shading);
    settings_.window = window ? *window : film_window(scene_.view.window, options.start_line);
    settings_.threads = options.threads;
    accelerator_.emplace(scene_, options.accel,
                         AccelMessages{console.note, console.warning, console.trace});
}

StudyRender StudyScene::render(const SamplingPlan& plan, std::uint64_t seed) {
    scene_.view.sample_resolution_x = plan.nx;
    scene_.view.sample_resolution_y = plan.ny;
    RenderSettings settings = settings_;
    SamplingSettings& sampling = settings.shading.sampling;
    sampling.seed = seed;
    sampling.adaptive = plan.adaptive;
    sampling.pixel_stop = {plan.probability, plan.pixel_variance};
    sampling.ray_stop = {plan.probability, plan.ray_variance};
    RenderObserver silent;
    RenderStatistics statistics;
    StudyRender out;
    out.film = rt::render(scene_, accelerator_->top(), settings, silent, statistics);
    const KindCounters& k = statistics.by_kind;
    out.spent.eye = k[RayKind::Eye].rays;
    out.spent.samples = k[RayKind::Eye].rays + k[RayKind::Reflected].rays +
                        k[RayKind::Refracted].rays + k[RayKind::Diffuse].rays +
                        k[RayKind::Probe].rays;
    out.spent.rays = statistics.counters.rays;
    return out;
}

}  // namespace rt::bench
