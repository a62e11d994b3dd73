#include "rt/wireframe/line_raster.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rt {

namespace {

int pixel_of(double coordinate, int low, int high) {
    return std::clamp(static_cast<int>(std::floor(coordinate)), low, high);
}

}  // namespace

void draw_line(Film& film, const PixelSegment& line, const Rgb& colour) {
    const PixelRect& w = film.window();
    PixelPoint a = line.from;
    PixelPoint b = line.to;
    const bool steep = std::fabs(b.y - a.y) > std::fabs(b.x - a.x);
    // Walk along the major axis (called u here), reading the minor one (v) off the line.
    const auto u = [steep](const PixelPoint& p) { return steep ? p.y : p.x; };
    const auto v = [steep](const PixelPoint& p) { return steep ? p.x : p.y; };
    if (u(a) > u(b)) {
        std::swap(a, b);
    }
    const int u_last = (steep ? film.view_height() : film.view_width()) - 1;
    const int v_last = (steep ? film.view_width() : film.view_height()) - 1;
    const int u_low = steep ? w.top : w.left;
    const int u_high = steep ? w.bottom : w.right;
    const int v_low = steep ? w.left : w.top;
    const int v_high = steep ? w.right : w.bottom;
    const double du = u(b) - u(a);
    const int first = std::max(pixel_of(u(a), 0, u_last), u_low);
    const int last = std::min(pixel_of(u(b), 0, u_last), u_high);
    for (int i = first; i <= last; ++i) {
        // The line at this column's centre, or at its end where it ends inside the column.
        const double at = std::clamp(i + 0.5, u(a), u(b));
        const double minor = du > 0.0 ? v(a) + (at - u(a)) * (v(b) - v(a)) / du : v(a);
        const int j = pixel_of(minor, 0, v_last);
        if (j >= v_low && j <= v_high) {
            film.set_pixel(steep ? j : i, steep ? i : j, colour);
        }
    }
}

}  // namespace rt
