#include "rt/shading/shading_settings.h"

namespace rt {

ShadingSettings earliest_version(ShadingSettings s, bool every_sample) {
    s.attenuate_rays = false;
    s.attenuate_feelers = false;
    s.feelers_stop_at_transparent = true;
    s.far_side_feelers = false;
    s.share_light_among_points = false;
    s.sampling.distribute = false;
    s.fuzzy = {};
    if (every_sample) {
        s.sampling.adaptive = false;  // the first version took every sample
    }
    return s;
}

}  // namespace rt
