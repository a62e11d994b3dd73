// What the illumination model needs to know about a ray's hit.
#pragma once

#include <cstdint>

#include "rt/accel/accelerator.h"
#include "rt/core/vec3.h"
#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

struct SurfacePoint {
    Vec3 position;
    Vec3 facing_normal;   ///< geometric normal turned toward where the ray came from
    Vec3 shading_normal;  ///< smoothed (-Po/-Pt, mark 1), inferred (-M) or mapped (-V), same side
    std::uint32_t polygon = 0;
    const Attribute* attribute = nullptr;
    Rgb color;                  ///< the attribute's colour, times the texture map's (-V)
    bool front = true;          ///< the ray arrived on the outward side
    double transmission = 0.0;  ///< the attribute's, or 0 where -Po forces opaqueness
};

/// Describes the hit of ray (unit direction) on its polygon.
SurfacePoint describe_hit(const Scene& scene, const ShadingSettings& settings, const Ray& ray,
                          const Hit& hit);

}  // namespace rt
