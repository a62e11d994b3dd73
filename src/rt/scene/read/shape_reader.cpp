#include "rt/scene/read/shape_reader.h"

#include <algorithm>

#include "rt/scene/read/dollar_lines.h"
#include "rt/scene/read/line_fields.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

Shape read_shape_line(const SourceText& source, const DollarLine& line, long index) {
    LineFields f(source, line);
    Shape s;
    s.index = index;
    s.where = f.location();
    // The manual's words: a sphere's centre, a point on a cylinder's axis, a cone's apex...
    s.first.x = f.number("the shape's first x (centre, axis point or apex)");
    s.first.y = f.number("the shape's first y");
    s.first.z = f.number("the shape's first z");
    s.radius_or_angle = f.number("the shape's radius or cone half-angle");
    // ...and another point on the axis (read but unused for spheres).
    s.second.x = f.number("the shape's second x (another point on the axis)");
    s.second.y = f.number("the shape's second y");
    s.second.z = f.number("the shape's second z");
    return s;
}

}  // namespace

std::vector<Shape> read_shape_file(const SourceText& source, Diagnostics& diagnostics) {
    DollarLineReader reader(source);
    DollarLine line;
    if (!reader.next(line)) {
        throw expected_found(source.at(source.last_line()), "the shape count", "end of file");
    }
    const std::int64_t count =
        count_from(source, line.tokens.front(), "the shape count", kMaxItemsPerFile);
    std::vector<Shape> shapes;
    shapes.reserve(static_cast<std::size_t>(std::min<std::int64_t>(count, 4096)));
    for (std::int64_t k = 0; k < count; ++k) {
        if (!reader.next(line)) {
            throw InputError(source.at(source.last_line()),
                             fmt::format("expected {} shapes, found {}", count, k));
        }
        shapes.push_back(read_shape_line(source, line, static_cast<long>(k)));
        const Shape& s = shapes.back();
        if (diagnostics.tracing()) {
            diagnostics.trace(fmt::format("{}: shape {}: {} {} {}", s.where.to_string(), s.index,
                                          show_point(s.first.x, s.first.y, s.first.z),
                                          show_number(s.radius_or_angle),
                                          show_point(s.second.x, s.second.y, s.second.z)));
        }
    }
    if (reader.next(line)) {
        diagnostics.warn(fmt::format("{}: lines after the {} shapes ignored",
                                     source.at(line.line).to_string(), count));
    }
    return shapes;
}

}  // namespace rt
