// The first items of a .scn (manual 2.2): the header line and the view (eye and look points,
// screen distance, view angles, sample resolution, view area, output matrix).
#pragma once

#include "rt/core/diagnostics.h"
#include "rt/scene/read/item_stream.h"
#include "rt/scene/scene.h"

namespace rt {

/// center lghtick sptncde octr graphmode normallength maxdepth maxdist, checked against limits.
SceneHeader read_header(ItemStream& scn, Diagnostics& diagnostics);

/// The view items in the manual's order; `eye_at` gets the line of the eye point. Without
/// auto-centering the eye and the look point must differ.
SceneView read_view(ItemStream& scn, const SceneHeader& header, SourceLocation& eye_at,
                    Diagnostics& diagnostics);

/// The output matrix against the view area: right == width or bottom == height is clamped with a
/// warning (the manual's own "0 0 512 399"); anything else outside, or reversed, is an error.
PixelRect checked_window(PixelRect window, int width, int height, const SourceLocation& at,
                         Diagnostics& diagnostics);

}  // namespace rt
