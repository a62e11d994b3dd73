#include "rt/app/run.h"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "rt/accel/brute_force.h"
#include "rt/accel/make_accelerator.h"
#include "rt/app/accel_debugging.h"
#include "rt/app/version.h"
#include "rt/core/diagnostics.h"
#include "rt/core/error.h"
#include "rt/core/text.h"
#include "rt/image/image_writer.h"
#include "rt/render/renderer.h"
#include "rt/scene/load_scene.h"

namespace rt {

namespace {

bool ends_with_scn(const std::string& name) {
    return name.size() > 4 && name.compare(name.size() - 4, 4, ".scn") == 0;
}

std::string join(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& w : words) {
        text += (text.empty() ? "" : " ") + w;
    }
    return text;
}

std::string utc_now() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm parts{};
    gmtime_r(&now, &parts);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
    return text;
}

ShadingSettings shading_settings(const Options& o) {
    ShadingSettings s;
    s.attenuation_distance = o.attenuation_distance;
    s.attenuation_constant = o.attenuation_constant;
    s.attenuate_rays = !o.disable_attenuation;
    s.attenuate_feelers = !o.disable_light_attenuation;
    s.shadow_feelers = !o.disable_shadow_feelers;
    s.feelers_stop_at_transparent = o.feelers_stop_at_transparent;
    s.reflection = !o.disable_reflection;
    s.both_sides_emit = !o.single_sided_emitters;
    s.far_side_feelers = o.specular_refraction_feelers;
    s.smooth_shaded_opaque = o.phong == PhongShading::Opaque;
    return s;
}

// The output matrix, cut at -L: "draws only from line L up" (row 0 is the top row).
FilmWindow render_window(const Scene& scene, const Options& o) {
    const PixelWindow& w = scene.view.window;
    FilmWindow window{w.left, w.top, w.right, w.bottom};
    if (o.start_line) {
        if (*o.start_line < window.top) {
            throw UsageError("-L" + std::to_string(*o.start_line) + ": line " +
                             std::to_string(*o.start_line) + " is above the window's top row " +
                             std::to_string(window.top));
        }
        window.bottom = std::min(window.bottom, *o.start_line);
    }
    return window;
}

// The intersection method: the scene header's (manual 2.2: 0 0 brute force, 1 depth octree,
// N 0 SEADS), unless --accel names another; -od overrides the octree depth.
AccelSettings accel_settings(const Scene& scene, const Options& o) {
    constexpr int kDefaultOctreeDepth = 8;
    constexpr int kDefaultSeadsResolution = 32;
    const SceneHeader& h = scene.header;
    AccelSettings a;
    a.kind = h.sptncde == 0   ? AccelKind::BruteForce
             : h.sptncde == 1 ? AccelKind::Octree
                              : AccelKind::Seads;
    a.octree_depth = h.sptncde == 1 ? h.octr : kDefaultOctreeDepth;
    a.seads_resolution = h.sptncde > 1 ? h.sptncde : kDefaultSeadsResolution;
    if (o.accel) {
        const std::optional<AccelKind> kind = accel_kind_from_name(*o.accel);
        if (!kind) {
            throw UsageError("--accel: expected brute, octree, seads, bvh or embree, found " +
                             quote_token(*o.accel));
        }
        a.kind = *kind;
    }
    if (o.octree_depth) {
        a.octree_depth = *o.octree_depth;
    }
    a.octlist_power = o.octlist_power;
    a.seed_size_power = o.seed_size_power;
    a.new_fillplane = o.new_fillplane;
    a.accept_near_hits = o.accept_near_hits;
    a.no_fudge = o.no_fudge;
    a.terminate_after_voxels = o.terminate_after_voxels;
    return a;
}

// A method the scene header asks for but this build lacks falls back to brute force, which gives
// the same picture; one asked for by --accel is refused.
std::unique_ptr<Accelerator> build_accelerator(const Scene& scene, const Options& o,
                                               const RunConsole& console) {
    const AccelSettings settings = accel_settings(scene, o);
    try {
        return make_accelerator(scene, settings);
    } catch (const NotImplementedError& e) {
        if (o.accel) {
            throw;
        }
        console.note(std::string(e.what()) +
                     "; every ray is tested against every polygon instead (the picture is the "
                     "same)");
        return make_brute_force(scene);
    }
}

class ConsoleObserver : public RenderObserver {
public:
    ConsoleObserver(const RunConsole& console, bool print_columns)
        : console_(console), print_columns_(print_columns) {}
    void row_done(int /*y*/, int rows_done, int rows_total) override {
        if (console_.progress) {
            console_.progress(rows_done, rows_total);
        }
    }
    bool wants_pixel_events() const override { return print_columns_; }
    void pixel_started(int x, int y) override {
        console_.trace("line " + std::to_string(y) + " column " + std::to_string(x));
    }
    bool should_stop() override { return console_.should_stop && console_.should_stop(); }

private:
    const RunConsole& console_;
    bool print_columns_;
};

void write_outputs(const Film& film, const Options& options) {
    if (!options.no_gro) {
        write_image(film, default_gro_path(options.scene));
    }
    for (const std::string& output : options.outputs) {
        write_image(film, output);
    }
}

}  // namespace

std::filesystem::path resolve_scene_path(const std::string& scene_argument) {
    if (ends_with_scn(scene_argument)) {
        return scene_argument;
    }
    const std::filesystem::path with_suffix = scene_argument + ".scn";
    if (std::filesystem::exists(with_suffix)) {
        return with_suffix;
    }
    if (std::filesystem::is_regular_file(scene_argument)) {
        return scene_argument;
    }
    return with_suffix;  // the reader's "cannot open" names the usual spelling
}

std::filesystem::path default_gro_path(const std::string& scene_argument) {
    std::filesystem::path name = std::filesystem::path(scene_argument).filename();
    if (ends_with_scn(name.string())) {
        name.replace_extension();
    }
    name += ".gro";
    return name;
}

RunOutcome run(const Options& options, const RunConsole& console) {
    for (const std::string& output : options.outputs) {
        (void)image_format_for(output);  // refuse an unknown format before hours of rendering
    }
    Diagnostics diagnostics;
    diagnostics.set_warning_sink(console.warning);
    diagnostics.set_note_sink(console.note);
    if (options.trace_parsing) {
        diagnostics.set_trace_sink(console.trace);
    }
    const Scene scene = load_scene(resolve_scene_path(options.scene), options.dialect, diagnostics);

    RenderSettings settings;
    settings.shading = shading_settings(options);
    settings.window = render_window(scene, options);
    settings.threads = options.threads;

    const DebuggedAccelerator accel =
        add_accel_debugging(scene, build_accelerator(scene, options, console), options, console);
    ConsoleObserver observer(console, options.print_columns);
    RenderStatistics statistics;
    Film film = render(scene, *accel.accel, settings, observer, statistics);
    if (accel.strike != nullptr) {
        console.note(accel.strike->summary());
    }
    film.mapping = {options.display_multiplier, options.clip_intensity};
    film.provenance = {options.scene, join(options.given_switches),
                       std::string("rt ") + std::string(kVersion), utc_now()};
    write_outputs(film, options);
    return statistics.interrupted ? RunOutcome::Interrupted : RunOutcome::Finished;
}

}  // namespace rt
