// -E angle: "sharp breaks in Phong-shaded objects if angle" (manual Appendix). Smooth shading
// averages the normals of the polygons around a vertex; across a crease sharper than the angle
// that average blurs an edge that should stay sharp. With -E each corner of a smooth polygon gets
// its own normal, averaged only over the smooth polygons at that vertex whose normals lie within
// the angle of this polygon's normal.
#pragma once

#include "rt/scene/scene.h"

namespace rt {

/// Fills scene.corner_normals (one per entry of scene.corners; zero for corners of polygons that
/// are not smooth). Where scene.model_normals has a normal, it is kept. `angle` in radians.
void compute_crease_normals(Scene& scene, double angle);

}  // namespace rt
