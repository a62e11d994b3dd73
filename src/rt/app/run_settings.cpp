#include "rt/app/run_settings.h"

#include <algorithm>
#include <string>

#include "rt/core/error.h"
#include "rt/scene/crease_normals.h"
#include "rt/shading/weight_scaling.h"

namespace rt {

ShadingSettings run_shading(const Options& options) {
    if (options.early == EarlyVersion::None) {
        return options.shading;
    }
    return earliest_version(options.shading, options.early == EarlyVersion::OldVersion);
}

// The output matrix, cut at -L: "draws only from line L up" (row 0 is the top row).
PixelRect render_window(const Scene& scene, const Options& o) {
    PixelRect window = scene.view.window;
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

void prepare_scene(Scene& scene, const Options& options, const ShadingSettings& shading) {
    if (options.crease_angle) {
        compute_crease_normals(scene, *options.crease_angle);
    }
    if (options.scale_weights) {
        scale_scene_weights(scene, shading);
    }
}

}  // namespace rt
