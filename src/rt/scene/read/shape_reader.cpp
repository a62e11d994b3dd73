#include "rt/scene/read/shape_reader.h"

#include <algorithm>

#include "rt/scene/read/counted_lines.h"
#include "rt/scene/read/line_fields.h"

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
    CountedLines file(source, "shape", "shapes");
    std::vector<Shape> shapes;
    shapes.reserve(static_cast<std::size_t>(std::min<std::int64_t>(file.count(), 4096)));
    for (std::int64_t k = 0; k < file.count(); ++k) {
        shapes.push_back(read_shape_line(source, file.next_item(), static_cast<long>(k)));
        const Shape& s = shapes.back();
        if (diagnostics.tracing()) {
            diagnostics.trace(fmt::format("{}: shape {}: {} {} {}", s.where.to_string(), s.index,
                                          show_point(s.first.x, s.first.y, s.first.z),
                                          show_number(s.radius_or_angle),
                                          show_point(s.second.x, s.second.y, s.second.z)));
        }
    }
    file.skip_the_rest(diagnostics);
    return shapes;
}

}  // namespace rt
