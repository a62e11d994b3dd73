#include "rt/app/run.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <optional>
#include <system_error>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator_stack.h"
#include "rt/accel/octree_depth_for.h"
#include "rt/app/input_digest.h"
#include "rt/app/inspection_runs.h"
#include "rt/app/interrupt.h"
#include "rt/app/memory_estimate.h"
#include "rt/app/output_checks.h"
#include "rt/app/profile_report.h"
#include "rt/app/resume.h"
#include "rt/app/run_settings.h"
#include "rt/app/switch_parser.h"
#include "rt/app/version.h"
#include "rt/core/diagnostics.h"
#include "rt/image/display_mapping.h"
#include "rt/image/image_writer.h"
#include "rt/image/picture_parts.h"
#include "rt/render/film_window.h"
#include "rt/render/random_rays.h"
#include "rt/render/ray_tree_bound.h"
#include "rt/render/renderer.h"
#include "rt/scene/near_plane.h"
#include "rt/scene/read/load_scene.h"
#include "rt/scene/read/model_scene.h"

#include <fmt/format.h>

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

class ConsoleObserver : public RenderObserver {
public:
    ConsoleObserver(const RunConsole& console, bool print_columns, bool print_samples)
        : console_(console), print_columns_(print_columns), print_samples_(print_samples) {}
    /// Rows go to the window too, at their place (the film window's left edge).
    void show_rows_in(PictureWindow* window, int left) {
        window_ = window;
        left_ = left;
    }
    void row_done(const RowDone& row) override {
        if (window_ != nullptr) {
            window_->board().show_row(left_, row.y, row.pixels);
        }
        samples_ += row.samples;
        if (console_.progress) {
            console_.progress(row.rows_done, row.rows_total, samples_);
        }
    }
    bool wants_pixel_events() const override { return print_columns_; }
    void pixel_started(int x, int y) override {
        console_.trace("line " + std::to_string(y) + " column " + std::to_string(x));
    }
    bool wants_sample_reports() const override { return print_samples_; }
    void pixel_sampled(int x, int y, const PixelReport& report) override {
        console_.trace("pixel " + std::to_string(x) + " " + std::to_string(y) + ": " +
                       std::to_string(report.samples) + " samples, " +
                       std::to_string(report.tree.distributed_intersections) +
                       " intersections distributing " +
                       std::to_string(report.tree.distributed_rays) + " rays, " +
                       std::to_string(report.probes + report.tree.probes) + " probes");
    }
    bool should_stop() override {
        return (console_.should_stop && console_.should_stop()) ||
               (window_ != nullptr && window_->closed());  // closing it stops as Ctrl-C does
    }

private:
    const RunConsole& console_;
    PictureWindow* window_ = nullptr;
    int left_ = 0;
    bool print_columns_;
    bool print_samples_;
    std::uint64_t samples_ = 0;
};

// -dd: the colour map (here, the display mapping) and every pixel's display value, in the order
// the rows were drawn (bottom up), with the intensity behind it.
void print_colors(const Film& film, const RunConsole& console) {
    const DisplayMapping& m = film.mapping;
    console.trace(fmt::format(
        "color map: display value = intensity x 255 x {} ({})", m.multiplier,
        m.clip ? "over 255 scaled down keeping the hue" : "not clipped: over 255 wraps"));
    const PixelRect& w = film.window();
    for (int y = w.bottom; y >= std::max(w.top, film.first_finished_row()); --y) {
        for (int x = w.left; x <= w.right; ++x) {
            const Rgb v = film.pixel(x, y);
            const std::array<std::uint8_t, 3> d = to_display(v, m);
            console.trace(fmt::format("pixel {} {}: {} {} {} (intensity {:.6g} {:.6g} {:.6g})", x,
                                      y, d[0], d[1], d[2], v.r, v.g, v.b));
        }
    }
}

// What made the picture, and how to show it; with what --resume and merge need to check that
// they join the same render.
void stamp(Film& film, const Options& options, const std::string& inputs) {
    film.mapping = options.display;
    film.provenance = {options.model.empty() ? options.scene : "--model " + options.model,
                       join(options.given_switches),
                       std::string("rt ") + std::string(kVersion),
                       utc_now(),
                       encode_arguments(options.render_arguments),
                       std::to_string(options.shading.sampling.seed),
                       inputs};
    if (options.tile) {
        film.part = {format_part_line(*options.tile)};
    }
}

// The files the picture goes to: the .gro (the resumed one with --resume, the part file with
// --tile, none with -n), then every --output.
std::vector<std::filesystem::path> output_paths(const Options& options) {
    std::vector<std::filesystem::path> paths;
    if (!options.resume.empty()) {
        paths.emplace_back(options.resume);
    } else if (!options.no_gro) {
        paths.emplace_back(gro_output_path(options));
    }
    paths.insert(paths.end(), options.outputs.begin(), options.outputs.end());
    return paths;
}

// Beside an existing output, where an interrupted render puts its partial picture:
// "twocubes.gro" -> "twocubes.partial.gro".
std::filesystem::path partial_path(const std::filesystem::path& path) {
    std::filesystem::path name = path;
    name.replace_extension();
    name += ".partial";
    name += path.extension();
    return name;
}

// Every output is attempted: one that cannot be written does not cost the others. The failures
// are reported together, one line each, as one IoError. An unfinished picture (Ctrl-C) never
// replaces an existing file: it goes beside it, and a picture without one finished line is not
// written at all. The file being resumed is the exception: it is the partial picture itself.
// Returns false when nothing was written for that reason.
bool write_outputs(const Film& film, const Options& options, const RunConsole& console) {
    const bool unfinished = !film.complete();
    if (unfinished && options.resume.empty() && film.first_finished_row() > film.window().bottom) {
        if (console.warning) {
            console.warning("stopped before the first line was finished: no file was written");
        }
        return false;
    }
    std::string failures;
    for (std::filesystem::path path : output_paths(options)) {
        std::error_code ec;
        if (unfinished && path != std::filesystem::path(options.resume) &&
            std::filesystem::exists(path, ec)) {
            const std::filesystem::path beside = partial_path(path);
            if (console.warning) {
                console.warning(fmt::format("{} is kept; the finished lines went to {}",
                                            path.string(), beside.string()));
            }
            path = beside;
        }
        try {
            write_image(film, path);
        } catch (const IoError& e) {
            failures += (failures.empty() ? "" : "\nrt: ") + std::string(e.what());
        }
    }
    if (!failures.empty()) {
        throw IoError(failures);
    }
    return true;
}

// Where maxdepth and surfaces that both reflect and transmit (or distribute their rays) let the
// ray tree grow past a million rays per sample, the user hears it before the render starts, with
// the two ways out.
void warn_of_exploding_tree(const Scene& scene, const ShadingSettings& shading,
                            const RunConsole& console) {
    if (shading.weight_cutoff > 0.0 || !console.warning) {
        return;  // the user has already bounded the tree
    }
    const RayTreeBound bound = ray_tree_bound(scene, shading);
    if (bound.rays_per_sample > kExplodingRayTree) {
        console.warning(fmt::format(
            "the ray tree may send up to {:.3g} rays per sample (maxdepth {}, and a hit can send "
            "{:g} secondary rays): the render may take very long; lower maxdepth in the scene "
            "header or give --cutoff W (e.g. --cutoff 0.01) to stop branches whose weight falls "
            "below W",
            bound.rays_per_sample, scene.header.maxdepth, bound.widest_branching));
    }
}

// The memory the run may take: --max-memory's, or what the system has left now.
std::optional<MemoryLimit> memory_limit(const Options& options) {
    if (options.max_memory_gib) {
        return MemoryLimit{
            static_cast<std::uint64_t>(std::min(*options.max_memory_gib * 1073741824.0, 1.8e19)),
            "--max-memory"};
    }
    return available_memory();
}

// Refuses a texture picture that would not fit in memory, with those read before it, before it is
// decoded; the refusal names the texture map's line.
PictureCheck picture_check(const Options& options) {
    std::optional<MemoryLimit> limit = memory_limit(options);
    if (!limit || options.debug_octree_interactive) {
        return {};
    }
    return [limit = *limit](const std::vector<TexturePicture>& pictures) {
        std::vector<MemoryPart> parts;
        parts.reserve(pictures.size());
        for (const TexturePicture& picture : pictures) {
            parts.push_back(texture_picture_part(picture.name, picture.width, picture.height));
        }
        try {
            check_memory(parts, limit);
        } catch (const UsageError& e) {
            throw UsageError(pictures.back().where.to_string() + ": " + e.what());
        }
    };
}

// The .scn, or with --model the scene made around the model, whose header names the octree at
// the depth suggested for its polygon count (--accel and -od still choose otherwise).
Scene read_scene(const Options& options, Diagnostics& diagnostics) {
    const ExitOnInterrupt nothing_to_keep;  // a read may block on a pipe
    if (options.model.empty()) {
        return load_scene(resolve_scene_path(options.scene), options.dialect, diagnostics,
                          options.dialect.textures ? picture_check(options) : PictureCheck{});
    }
    Scene scene = model_scene(options.model, options.dialect, diagnostics);
    scene.header.sptncde = 1;
    scene.header.octr = octree_depth_for(scene);
    return scene;
}

// -p's report (the method's lines under it), or with -de alone the exit culling's lines.
void report_profile(const Options& options, const RunConsole& console, const Scene& scene,
                    const AcceleratorStack& stack, const PhaseTimes& times,
                    const KindCounters& counters) {
    if (!console.report) {
        return;
    }
    const Accelerator& accel = stack.top();
    if (options.profile) {
        std::string text = profile_report(
            {accel.name(), scene.polygons.size(), accel.memory_bytes(), times, &counters});
        for (const std::string& line : stack.report_lines()) {
            text += "  " + line + "\n";
        }
        console.report(text);
    } else if (options.accel.check_exit_culling) {
        for (const std::string& line : stack.report_lines()) {
            console.report(line + "\n");
        }
    }
}

// The intersection method, with exit culling in front unless -De (or unless the scene has more
// polygons than the render has rays from the eye for it to cull); a signal ends the program at
// once while it is built (a big build never looks at the flag).
AcceleratorStack build_accelerator_stack(const Scene& scene, const Options& options,
                                         const RenderSettings& render, const RunConsole& console) {
    const ExitOnInterrupt nothing_to_keep;
    AcceleratorStackSettings settings = run_accelerator_stack(options);
    // -r fires rays from anywhere, not from the eye.
    settings.most_eye_rays = options.random_rays ? 0 : most_eye_rays(scene, render);
    return AcceleratorStack(scene, settings, {console.note, console.warning, console.trace});
}

// The picture's window, showing the wireframe (manual 1.2.2: "First, the outline (called a
// wire-frame) of the scene will be drawn"); null when the console opens none. -doi and -r draw
// no picture.
std::unique_ptr<PictureWindow> open_window(const Scene& scene, const Options& options,
                                           const PixelRect& window, const RunConsole& console) {
    if (!console.open_window || options.debug_octree_interactive || options.random_rays) {
        return nullptr;
    }
    std::unique_ptr<PictureWindow> shown;
    {
        // A display that takes the connection and never answers blocks the opening for good.
        const ExitOnInterrupt nothing_to_keep;
        shown =
            console.open_window({"rt: " + (options.model.empty() ? options.scene : options.model),
                                 scene.view.width,
                                 scene.view.height,
                                 options.display,
                                 false,
                                 {},
                                 {}});
    }
    if (shown && !options.wireframe_only) {  // -w shows the one it writes
        shown->board().show_film(wireframe_picture(scene, options, window, console));
    }
    return shown;
}

// The rows an interrupted render finished, in the window (--resume).
void show_finished_rows(const Film& film, PictureBoard& board) {
    const PixelRect& w = film.window();
    const auto row_floats = static_cast<std::size_t>(w.width()) * 3;
    for (int y = std::max(w.top, film.first_finished_row()); y <= w.bottom; ++y) {
        board.show_row(w.left, y,
                       std::span<const float>(film.data())
                           .subspan(static_cast<std::size_t>(y - w.top) * row_floats, row_floats));
    }
}

// The outputs are written: the window stays until the viewer is done with it.
void close_window(std::unique_ptr<PictureWindow> window, const RunConsole& console) {
    if (window && !window->closed() && !window->lost() && console.keep_window_open) {
        console.keep_window_open(*window);
    }
}

// -doi's session and -w's wireframe, which trace nothing; true when the run is over.
bool run_without_tracing(const Scene& scene, const Options& options, const PixelRect& window,
                         const std::string& inputs, const RunConsole& console,
                         std::unique_ptr<PictureWindow>& shown) {
    if (options.debug_octree_interactive) {
        inspect_octree(scene, options, console);
        return true;
    }
    if (options.wireframe_only) {
        Film film = wireframe_picture(scene, options, window, console);
        stamp(film, options, inputs);
        if (shown) {
            shown->board().show_film(film);
        }
        write_outputs(film, options, console);
        close_window(std::move(shown), console);
        return true;
    }
    if (options.draw_octree && !shown) {
        console.note(
            "-oo draws the octree's boxes on the wireframe, which only -w writes; the "
            "picture is ray traced as usual");
    }
    return false;
}

// Eye rays start on the screen, so polygons nearer the eye than screendist are not seen: said once,
// with the screendist that would show them.
void warn_near_plane(const Scene& scene, const RunConsole& console) {
    const NearPlaneReport near = polygons_before_screen(scene);
    if (near.polygons == 0 || !console.warning) {
        return;
    }
    const double showing = screendist_showing(near);
    console.warning(fmt::format(
        "{} between the eye and the screen (screendist {:g}), where eye rays, starting on "
        "the screen, do not see {}{}",
        near.polygons == 1 ? std::string("1 polygon lies")
                           : fmt::format("{} polygons lie", near.polygons),
        scene.view.screen_distance, near.polygons == 1 ? "it" : "them",
        showing > 0.0 ? fmt::format(": a screendist of {:g} would show {}", showing,
                                    near.polygons == 1 ? "it" : "them")
                      : std::string(": one reaches the eye itself, so no screendist shows it "
                                    "whole")));
}

// Refuses a render that would not fit in memory, before its film or method is allocated, or
// whose outputs would not fit on their disks.
void check_resources(const Scene& scene, const Options& options, const PixelRect& window,
                     const RunConsole& console) {
    if (options.debug_octree_interactive) {
        return;
    }
    if (!options.random_rays) {
        for (const std::filesystem::path& path : output_paths(options)) {
            check_output_space(path, window);
        }
    }
    const bool window_opens = console.open_window && !options.random_rays;
    std::optional<MemoryLimit> limit = memory_limit(options);
    if (limit && !options.max_memory_gib) {
        // Measured now, what the system has left is short of the texture pictures read already;
        // the estimate counts them with the rest.
        for (const TextureImage& picture : scene.texture_images) {
            limit->bytes += picture.rgb.size();
        }
    }
    if (limit) {
        check_memory(estimate_render_memory(scene, options, window, window_opens), *limit);
    }
}

}  // namespace

std::filesystem::path resolve_scene_path(const std::string& scene_argument) {
    if (ends_with_scn(scene_argument)) {
        return scene_argument;
    }
    // Names the system cannot look up (too long, a loop of links) count as absent here: the
    // reader's "cannot open" then says why.
    std::error_code error;
    std::filesystem::path with_suffix = scene_argument + ".scn";
    if (std::filesystem::exists(with_suffix, error)) {
        return with_suffix;
    }
    // Anything else that exists (a pipe such as the shell's <(...), a device, refused by the
    // reader with its reason) is the scene as given.
    if (std::filesystem::exists(scene_argument, error) &&
        !std::filesystem::is_directory(scene_argument, error)) {
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

std::filesystem::path model_gro_path(const std::string& model_argument) {
    std::filesystem::path name = std::filesystem::path(model_argument).stem();
    name += ".gro";
    return name;
}

std::filesystem::path part_path(const std::filesystem::path& gro, PicturePart part) {
    std::filesystem::path name = gro;
    name.replace_extension();
    name += fmt::format(".part-{}-of-{}.gro", part.index, part.count);
    return name;
}

std::filesystem::path gro_output_path(const Options& options) {
    const std::filesystem::path gro =
        options.model.empty() ? default_gro_path(options.scene) : model_gro_path(options.model);
    return options.tile ? part_path(gro, *options.tile) : gro;
}

namespace {

// Refuses an unknown format or a folder that cannot take the file before hours of rendering
// (-doi and -r write no .gro, only the --output files are checked).
void check_outputs(const Options& options) {
    const bool writes_gro = !options.debug_octree_interactive && !options.random_rays;
    for (const std::filesystem::path& output : output_paths(options)) {
        if (writes_gro || std::find(options.outputs.begin(), options.outputs.end(),
                                    output.string()) != options.outputs.end()) {
            (void)image_format_for(output);
            check_output_folder(output);
        }
    }
}

// The settings of the render, the scene prepared for them (-E, -K, ...); with --resume, once the
// inputs are checked to be the interrupted render's.
RenderSettings render_settings(Scene& scene, const Options& options, const RunConsole& console,
                               const Film* resume, const std::string& inputs) {
    RenderSettings settings;
    settings.shading = run_shading(options);
    prepare_scene(scene, options, settings.shading);
    settings.window = film_window(scene.view.window, options.start_line);
    if (options.tile) {
        settings.window = part_window(settings.window, *options.tile);
    }
    settings.threads = options.threads;
    settings.stop_now = console.stop_now;
    if (resume != nullptr) {
        check_resumable(*resume, inputs, scene.view.width, scene.view.height, settings.window);
        settings.resume = resume;
    }
    if (!options.wireframe_only && !options.debug_octree_interactive && !options.random_rays) {
        warn_of_exploding_tree(scene, settings.shading, console);
    }
    return settings;
}

// What the render found on its way: the strike check's summary, samples counted as black.
void report_render(const AcceleratorStack& stack, const RenderStatistics& statistics,
                   const RunConsole& console) {
    if (stack.strike_check() != nullptr) {
        console.note(stack.strike_check()->summary());
    }
    if (statistics.unrepresentable_samples > 0) {
        console.warning(
            fmt::format("{} samples had an intensity that is not a finite number "
                        "within the float range; they were counted as black",
                        statistics.unrepresentable_samples));
    }
}

// The run itself; `resume` is the interrupted picture to complete, or null.
RunOutcome render_run(const Options& options, const RunConsole& console, const Film* resume,
                      const RenderStep& step) {
    check_outputs(options);
    Diagnostics diagnostics;
    diagnostics.set_warning_sink(console.warning);
    diagnostics.set_note_sink(console.note);
    if (options.trace_parsing) {
        diagnostics.set_trace_sink(console.trace);
    }
    using Clock = std::chrono::steady_clock;
    const auto seconds_since = [](Clock::time_point start) {
        return std::chrono::duration<double>(Clock::now() - start).count();
    };
    PhaseTimes times;
    auto phase = Clock::now();
    Scene scene = read_scene(options, diagnostics);
    const std::string inputs = input_digest(scene);
    times.load_seconds = seconds_since(phase);

    const RenderSettings settings = render_settings(scene, options, console, resume, inputs);
    check_resources(scene, options, settings.window, console);
    std::unique_ptr<PictureWindow> shown = open_window(scene, options, settings.window, console);
    if (shown && resume != nullptr) {
        show_finished_rows(*resume, shown->board());  // over the wireframe, as if just drawn
    }
    if (run_without_tracing(scene, options, settings.window, inputs, console, shown)) {
        return RunOutcome::Finished;
    }

    warn_near_plane(scene, console);
    phase = Clock::now();
    const AcceleratorStack stack = build_accelerator_stack(scene, options, settings, console);
    const Accelerator* accel = &stack.top();
    times.build_seconds = seconds_since(phase);
    const auto print_profile = [&](const KindCounters& counters) {
        report_profile(options, console, scene, stack, times, counters);
    };
    if (options.random_rays) {
        // -r: as many random rays as the window has pixels; no picture, so no output file.
        phase = Clock::now();
        const auto count = static_cast<std::uint64_t>(settings.window.width()) *
                           static_cast<std::uint64_t>(settings.window.height());
        const KindCounters counters =
            fire_random_rays(scene, *accel, count, options.shading.sampling.seed, options.threads);
        times.trace_seconds = seconds_since(phase);
        console.note("-r: fired " + std::to_string(count) + " random rays; no picture is written");
        print_profile(counters);
        return RunOutcome::Finished;
    }
    ConsoleObserver observer(console, options.print_columns, options.debug_chi_square);
    observer.show_rows_in(shown.get(), settings.window.left);
    RenderStatistics statistics;
    phase = Clock::now();
    if (console.progress) {
        console.progress(0, settings.window.height(), 0);
    }
    std::optional<Film> rendered = step ? step(scene, *accel, settings, observer, statistics)
                                        : render(scene, *accel, settings, observer, statistics);
    if (!rendered) {
        return RunOutcome::Finished;  // a helping process of a cluster run: rank 0 writes
    }
    Film film = std::move(*rendered);
    times.trace_seconds = seconds_since(phase);
    report_render(stack, statistics, console);
    stamp(film, options, inputs);
    if (options.debug_color) {
        print_colors(film, console);
    }
    phase = Clock::now();
    const bool kept = write_outputs(film, options, console);
    times.write_seconds = seconds_since(phase);
    print_profile(statistics.by_kind);
    close_window(std::move(shown), console);
    if (!statistics.interrupted) {
        return RunOutcome::Finished;
    }
    return kept ? RunOutcome::Interrupted : RunOutcome::InterruptedWithNothingKept;
}

}  // namespace

RunOutcome run(const Options& options, const RunConsole& console, const RenderStep& step) {
    if (options.resume.empty()) {
        return render_run(options, console, nullptr, step);
    }
    if (step) {
        // The finished rows are in one file on one machine; the ranks would render them again.
        throw UsageError("--resume completes a picture on one process: run it without mpirun");
    }
    const ResumePlan plan = plan_resume(options);
    return render_run(plan.options, console, &plan.done, step);
}

}  // namespace rt
