// Drawing a line of the picture into a film: one pixel per column (or per row, for a steep
// line), the pixel the line crosses at that column's centre, so the line is unbroken, one pixel
// thick, and every pixel drawn is one the line passes through. Pixels are chosen over the whole
// view and only those inside the film's window are set, so a window (the output matrix, -L)
// shows exactly what the whole picture shows there.
#pragma once

#include "rt/core/rgb.h"
#include "rt/image/film.h"
#include "rt/wireframe/line_projection.h"

namespace rt {

/// Sets the pixels of `line` inside the film's window to `colour`. The segment is expected inside
/// the view area (LineProjection clips it); points on the view's far edges belong to its last
/// column or row.
void draw_line(Film& film, const PixelSegment& line, const Rgb& colour);

}  // namespace rt
