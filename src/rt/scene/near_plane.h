// Polygons between the eye and the screen: eye rays start on the screen (manual 2.2), so what lies
// nearer than screendist is not seen. The run warns about them once.
#pragma once

#include <cstddef>

#include "rt/scene/scene.h"

namespace rt {

struct NearPlaneReport {
    std::size_t polygons = 0;  ///< polygons with a part in view between the eye and the screen
    /// The nearest depth of such a part along the view direction; a screendist below it shows
    /// them all. 0 when a polygon reaches the eye itself.
    double nearest_depth = 0.0;
};

/// Counts the polygons with a part of positive area inside the view pyramid (the view area's
/// angles) and nearer the eye than the screen.
NearPlaneReport polygons_before_screen(const Scene& scene);

/// A screendist that shows every part `report` found: below its nearest depth, rounded down to
/// two significant digits; 0 when there is none (a polygon reaches the eye).
double screendist_showing(const NearPlaneReport& report);

}  // namespace rt
