// The point light sources shadow feelers aim at (manual 2.2, lghtick): every vertex of every
// emissive polygon (1) or every emissive polygon's centre (2).
#pragma once

#include <cstdint>
#include <vector>

#include "rt/core/rgb.h"
#include "rt/core/vec3.h"
#include "rt/scene/scene.h"

namespace rt {

struct PointLight {
    Vec3 position;
    Rgb intensity;              ///< the emitter's colour times its emission weight, shared out
    std::uint32_t polygon = 0;  ///< the emissive polygon it belongs to
};

/// Collects the point lights for the header's lghtick (0 gives none). Each emissive polygon is
/// one light of intensity colour * emission, split equally among its point sources, so that
/// lghtick 1 and 2 light a scene equally brightly.
/// With `share` false (-Oi, the earliest version) every point source carries the polygon's whole
/// intensity, so lghtick 1 lights a scene once per vertex.
std::vector<PointLight> collect_point_lights(const Scene& scene, int lghtick, bool share = true);

}  // namespace rt
