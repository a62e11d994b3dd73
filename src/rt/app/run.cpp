#include "rt/app/run.h"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "rt/accel/brute_force.h"
#include "rt/app/version.h"
#include "rt/core/diagnostics.h"
#include "rt/core/error.h"
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

void note_spatial_encoding(const Scene& scene, const RunConsole& console) {
    const SceneHeader& h = scene.header;
    if (h.sptncde == 0) {
        return;
    }
    const std::string asked = h.sptncde == 1 ? "an octree of depth " + std::to_string(h.octr)
                                             : "SEADS with " + std::to_string(h.sptncde) +
                                                   " voxels a side";
    console.note("the scene asks for " + asked +
                 "; spatial encoding is not implemented yet, so every ray is tested against "
                 "every polygon (the picture is the same)");
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
    note_spatial_encoding(scene, console);

    RenderSettings settings;
    settings.shading = shading_settings(options);
    settings.window = render_window(scene, options);
    settings.threads = options.threads;

    const std::unique_ptr<Accelerator> accel = make_brute_force(scene);
    ConsoleObserver observer(console, options.print_columns);
    RenderStatistics statistics;
    Film film = render(scene, *accel, settings, observer, statistics);
    film.mapping = {options.display_multiplier, options.clip_intensity};
    film.provenance = {options.scene, join(options.given_switches),
                       std::string("rt ") + std::string(kVersion), utc_now()};
    write_outputs(film, options);
    return statistics.interrupted ? RunOutcome::Interrupted : RunOutcome::Finished;
}

}  // namespace rt
