#include "rt/app/run_settings.h"

#include <algorithm>

#include "rt/scene/crease_normals.h"
#include "rt/shading/weight_scaling.h"

namespace rt {

AcceleratorStackSettings run_accelerator_stack(const Options& options) {
    AcceleratorStackSettings settings = options.accel;
    settings.method.build_threads = static_cast<unsigned>(std::max(options.threads, 0));
    return settings;
}

ShadingSettings run_shading(const Options& options) {
    if (options.early == EarlyVersion::None) {
        return options.shading;
    }
    return earliest_version(options.shading, options.early == EarlyVersion::OldVersion);
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
