// Warn lights (manual Appendix -Wr -Wc -Wt; Rogers, Procedural Elements): emissive polygons that
// shine mostly along their normal. A factor on each shadow feeler's light; pure functions, wired
// into the shadow feeler by its caller. docs/illumination-models.md has the formulas.
//
// Use, per shadow feeler from surface point P to point light S of emitter E:
//   target = warn_feeler_target(settings, emitter, S, P);   // S, or S displaced for -Wt
//   feel the light along P -> target; for -Wt, crosses = the feeler met E's polygon on the way
//   light *= warn_factor(settings, emitter, normalize(P - target), crosses);
#pragma once

#include "rt/core/vec3.h"

namespace rt {

enum class WarnMode {
    None,       ///< no Warn lights: factor 1
    Rogers,     ///< -Wr: cos^N(x)
    Conical,    ///< -Wc angle: cos^N(x), and 0 when x > angle
    Thibadeau,  ///< -Wt dist: aim at the source displaced behind the polygon; Rogers if the
                ///< feeler crosses the polygon, else 0
};

struct WarnSettings {
    WarnMode mode = WarnMode::None;
    double cone_angle = 0.0;    ///< -Wc: the cut-off angle, radians
    double displacement = 0.0;  ///< -Wt: how far the point source moves behind the polygon
};

/// The emissive polygon a point light belongs to, as the Warn lights see it.
struct WarnEmitter {
    Vec3 normal;                  ///< unit normal of the emissive polygon
    double exponent = 2.0;        ///< N: the emitter attribute's pow (specular_exponent)
    bool both_sides_emit = true;  ///< false with -Db: only the side the normal points to emits
};

/// The cosine of the angle x between the feeler's direction `light_to_point` (unit, from the light
/// toward the lit point) and the emitter's normal on the side facing the point: |N.d| when both
/// sides emit, else N.d (negative when the point is behind the emitter).
double warn_cosine(const WarnEmitter& emitter, const Vec3& light_to_point);

/// Rogers's factor cos^N(x), 0 when cos x <= 0 (the point is not on an emitting side).
double rogers_factor(const WarnEmitter& emitter, const Vec3& light_to_point);

/// The point the shadow feeler from `point` aims at: `light_position` itself, or for -Wt the light
/// displaced by `displacement` along the emitter's normal away from the point's side (the
/// negative normal for a point in front; with both sides emitting, a point behind the polygon gets
/// the light displaced along +normal).
Vec3 warn_feeler_target(const WarnSettings& settings, const WarnEmitter& emitter,
                        const Vec3& light_position, const Vec3& point);

/// -Wt: Rogers's factor when the line from the point to the displaced source crosses the emitter
/// polygon, else 0. `source_to_point` is unit, from the displaced source toward the point.
double thibadeau_factor(const WarnEmitter& emitter, const Vec3& source_to_point,
                        bool crosses_emitter);

/// The factor on the light a feeler brings: 1 for None, rogers_factor for -Wr, the same cut off
/// beyond cone_angle for -Wc, thibadeau_factor for -Wt. `light_to_point` is unit, from the
/// feeler's target (warn_feeler_target) toward the point; `crosses_emitter` matters only for -Wt.
double warn_factor(const WarnSettings& settings, const WarnEmitter& emitter,
                   const Vec3& light_to_point, bool crosses_emitter = false);

}  // namespace rt
