#include "rt/scene/read/scn_view.h"

#include <algorithm>
#include <cmath>

#include "rt/core/text.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

// An output matrix edge one past the last column or row (`size`) is taken as the last one, with
// a warning.
void pull_onto_last(int& edge, int size, std::string_view edge_name, std::string_view line,
                    const SourceLocation& at, Diagnostics& diagnostics) {
    if (edge == size) {
        edge = size - 1;
        diagnostics.warn(
            fmt::format("{}: the output matrix's {} {} is one past the last {}; "
                        "using {}",
                        at.to_string(), edge_name, size, line, edge));
    }
}

int small_integer(ItemStream& scn, std::string_view what, int lo, int hi) {
    return static_cast<int>(integer_in(scn.source(), scn.take(what), what, lo, hi));
}

// A number strictly between lo and hi (hi < 0: no upper bound).
double number_between(ItemStream& scn, std::string_view what, double lo, double hi) {
    const Token token = scn.take(what);
    const double value = number_from(scn.source(), token, what);
    if (value <= lo || (hi >= 0 && value >= hi)) {
        const std::string range = hi >= 0 ? fmt::format("between {:g} and {:g}", lo, hi)
                                          : fmt::format("more than {}", lo);
        throw expected_found(location_of(scn.source(), token), fmt::format("{} ({})", what, range),
                             quote_token(token.text));
    }
    return value;
}

Vec3 point(ItemStream& scn, const std::string& name) {
    Vec3 p;
    p.x = scn.coordinate("the " + name + "'s x");
    p.y = scn.coordinate("the " + name + "'s y");
    p.z = scn.coordinate("the " + name + "'s z");
    return p;
}

void trace(ItemStream& scn, Diagnostics& diagnostics, const std::string& text) {
    if (diagnostics.tracing()) {
        diagnostics.trace(scn.source().at(scn.line()).to_string() + ": " + text);
    }
}

// One number or two, decided per line: a second number counts only on the first one's line.
void read_sample_resolution(ItemStream& scn, SceneView& view) {
    constexpr int kMax = kMaxSampleResolution;
    view.sample_resolution_x = small_integer(scn, "the sample resolution", 1, kMax);
    view.sample_resolution_y = view.sample_resolution_x;
    if (scn.next_on_same_line() && parse_double(scn.peek()->text)) {
        view.sample_resolution_y = small_integer(scn, "the sample resolution y", 1, kMax);
    }
}

void read_window(ItemStream& scn, SceneView& view, Diagnostics& diagnostics) {
    constexpr int kFar = 1'000'000'000;  // keeps the arithmetic below in range
    PixelRect w;
    w.left = small_integer(scn, "the output matrix's left", -kFar, kFar);
    const SourceLocation at = scn.source().at(scn.line());
    w.top = small_integer(scn, "the output matrix's top", -kFar, kFar);
    w.right = small_integer(scn, "the output matrix's right", -kFar, kFar);
    w.bottom = small_integer(scn, "the output matrix's bottom", -kFar, kFar);
    view.window = checked_window(w, view.width, view.height, at, diagnostics);
}

}  // namespace

SceneHeader read_header(ItemStream& scn, Diagnostics& diagnostics) {
    SceneHeader h;
    h.center = small_integer(scn, "the header's center", 0, 1);
    h.lghtick = small_integer(scn, "the header's lghtick", 0, 2);
    h.sptncde = small_integer(scn, "the header's sptncde", 0, kMaxSeadsVoxels);
    h.octr = small_integer(scn, "the header's octr", 0, kMaxOctreeDepth);
    h.graphmode = small_integer(scn, "the header's graphmode", -1'000'000, 1'000'000);
    h.normallength = scn.number("the header's normallength");
    h.maxdepth = small_integer(scn, "the header's maxdepth", 0, kMaxRayDepth);
    const Token maxdist = scn.take("the header's maxdist");
    h.maxdist = number_from(scn.source(), maxdist, "the header's maxdist");
    if (h.maxdist < 0) {
        throw expected_found(location_of(scn.source(), maxdist), "the header's maxdist (0 or more)",
                             quote_token(maxdist.text));
    }
    scn.end_item();
    trace(scn, diagnostics,
          fmt::format("header: center {} lghtick {} sptncde {} octr {} graphmode {} normallength "
                      "{} maxdepth {} maxdist {}",
                      h.center, h.lghtick, h.sptncde, h.octr, h.graphmode, h.normallength,
                      h.maxdepth, h.maxdist));
    return h;
}

SceneView read_view(ItemStream& scn, const SceneHeader& header, SourceLocation& eye_at,
                    Diagnostics& diagnostics) {
    SceneView v;
    const Token* first = scn.peek();
    eye_at = first ? location_of(scn.source(), *first) : scn.end_location();
    v.eye = point(scn, "eye point");
    v.look = point(scn, "look point");
    scn.end_item();
    trace(scn, diagnostics,
          "eye " + show_point(v.eye.x, v.eye.y, v.eye.z) + " look " +
              show_point(v.look.x, v.look.y, v.look.z));
    if (header.center == 0 && v.eye == v.look) {
        throw InputError(eye_at, "the eye point and the look point are the same " +
                                     show_point(v.eye.x, v.eye.y, v.eye.z));
    }
    // Eye rays start on the screen and point away from the eye: a screen so close that the eye's
    // own rounding swallows it gives rays of no direction (a black picture at 1e-100) or bent
    // ones. A millionth of the eye's largest coordinate (or of 1) keeps them true to 1e-9.
    const double eye_scale =
        std::max({1.0, std::fabs(v.eye.x), std::fabs(v.eye.y), std::fabs(v.eye.z)});
    v.screen_distance = number_between(scn, "the screen distance", kLeastScreenDistance * eye_scale,
                                       kMaxCoordinate);
    scn.end_item();
    trace(scn, diagnostics, "screendist " + show_number(v.screen_distance));
    v.view_angle_x_degrees = number_between(scn, "the view angle x in degrees", 0.0, 180.0);
    v.view_angle_y_degrees = number_between(scn, "the view angle y in degrees", 0.0, 180.0);
    scn.end_item();
    trace(scn, diagnostics,
          fmt::format("view angles {} {}", v.view_angle_x_degrees, v.view_angle_y_degrees));
    read_sample_resolution(scn, v);
    scn.end_item();
    trace(scn, diagnostics,
          fmt::format("sample resolution {} {}", v.sample_resolution_x, v.sample_resolution_y));
    v.width = small_integer(scn, "the view area's width in pixels", 1, kMaxViewSide);
    v.height = small_integer(scn, "the view area's height in pixels", 1, kMaxViewSide);
    scn.end_item();
    trace(scn, diagnostics, fmt::format("view area {} x {}", v.width, v.height));
    read_window(scn, v, diagnostics);
    scn.end_item();
    const PixelRect& w = v.window;
    trace(scn, diagnostics,
          fmt::format("output matrix {} {} {} {}", w.left, w.top, w.right, w.bottom));
    return v;
}

PixelRect checked_window(PixelRect w, int width, int height, const SourceLocation& at,
                         Diagnostics& diagnostics) {
    const std::string given = fmt::format("{} {} {} {}", w.left, w.top, w.right, w.bottom);
    pull_onto_last(w.right, width, "right edge", "column", at, diagnostics);
    pull_onto_last(w.bottom, height, "bottom edge", "row", at, diagnostics);
    const bool inside = w.left >= 0 && w.top >= 0 && w.right < width && w.bottom < height;
    if (!inside) {
        throw InputError(at, fmt::format("the output matrix {} is outside the {} x {} view area "
                                         "(columns 0 to {}, rows 0 to {})",
                                         given, width, height, width - 1, height - 1));
    }
    if (w.left > w.right || w.top > w.bottom) {
        throw InputError(at, fmt::format("the output matrix {} is reversed: it reads left top "
                                         "right bottom",
                                         given));
    }
    return w;
}

}  // namespace rt
