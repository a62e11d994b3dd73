#include "rt/app/inspection_runs.h"

#include "rt/accel/make_accelerator.h"
#include "rt/accel/octree/octree_session.h"
#include "rt/core/error.h"
#include "rt/wireframe/wireframe.h"

#include <fmt/format.h>

namespace rt {

std::unique_ptr<Octree> octree_to_inspect(const Scene& scene, const Options& options,
                                          std::string_view what, const RunConsole& console) {
    AccelSettings settings = method_for_scene(scene, options.accel.method);
    const AccelKind method = *settings.kind;
    settings.kind = AccelKind::Octree;
    settings = method_for_scene(scene, settings);  // the depth, when the method was another
    if (method != AccelKind::Octree && console.note) {
        console.note(
            fmt::format("{}: the intersection method is {}; {} shows the octree "
                        "--accel octree would build (depth {})",
                        what, accel_kind_name(method), what, *settings.octree.depth));
    }
    return std::make_unique<Octree>(scene, settings);
}

Film wireframe_picture(const Scene& scene, const Options& options, const PixelRect& window,
                       const RunConsole& console) {
    std::unique_ptr<Octree> octree;
    if (options.draw_octree) {
        octree = octree_to_inspect(scene, options, "-oo", console);
    }
    Film film(scene.view.width, scene.view.height, window);
    draw_wireframe(scene, {scene.header.normallength, octree ? &octree->tree() : nullptr}, film);
    return film;
}

void inspect_octree(const Scene& scene, const Options& options, const RunConsole& console) {
    if (console.commands == nullptr || console.answers == nullptr) {
        throw UsageError("-doi needs a place to read commands from");
    }
    const std::unique_ptr<Octree> octree = octree_to_inspect(scene, options, "-doi", console);
    const int failed =
        run_octree_session(scene, *octree, {*console.commands, *console.answers, console.prompt});
    if (console.note) {
        console.note(
            fmt::format("-doi: session over ({} command{} failed); no picture is "
                        "rendered",
                        failed, failed == 1 ? "" : "s"));
    }
}

}  // namespace rt
