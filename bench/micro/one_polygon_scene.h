// A scene of one regular polygon and a batch of rays aimed around it, for timing the ray-polygon
// test alone.
#pragma once

#include <vector>

#include "rt/core/ray.h"
#include "rt/scene/scene.h"

namespace rt::bench {

/// One regular polygon of `corners` corners, radius 1, centred on the origin in the plane z = 0.
Scene regular_polygon_scene(int corners);

/// `count` rays from random points above the plane to random points of the square [-1.2, 1.2]^2:
/// a mix of hits and misses, the same every run.
std::vector<Ray> rays_around_unit_polygon(int count);

}  // namespace rt::bench
