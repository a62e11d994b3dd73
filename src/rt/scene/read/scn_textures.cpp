#include "rt/scene/read/scn_textures.h"

#include "rt/core/text.h"
#include "rt/scene/read/counted_lines.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

NamedFile file_name(ItemStream& scn, const std::string& what) {
    const Token token = scn.take(what);
    return {std::string(token.text), location_of(scn.source(), token)};
}

// Rows and columns of cells; the grid's points, (rows + 1) x (columns + 1), are checked against
// the limit here, before any file is read.
void read_grid_size(ItemStream& scn, ScnTexturedSurface& s) {
    const std::string of = " of texture-mapped surface '" + s.polygon_file.name + "'";
    const Token rows = scn.take("the rows of cells" + of);
    s.rows = integer_in(scn.source(), rows, "the rows of cells" + of, 1, kMaxGridPoints);
    s.columns = integer_in(scn.source(), scn.take("the columns of cells" + of),
                           "the columns of cells" + of, 1, kMaxGridPoints);
    if ((s.rows + 1) > kMaxGridPoints / (s.columns + 1)) {
        throw InputError(location_of(scn.source(), rows),
                         fmt::format("the grid{} has {} x {} cells, more than the limit of {} "
                                     "points",
                                     of, s.rows, s.columns, kMaxGridPoints));
    }
}

ScnTexturedSurface read_textured_surface(ItemStream& scn) {
    ScnTexturedSurface s;
    const Token first = scn.take("the texture-mapped surface's attribute number");
    s.where = location_of(scn.source(), first);
    s.attribute_number = static_cast<long>(
        integer_from(scn.source(), first, "the texture-mapped surface's attribute number"));
    s.polygon_file = file_name(scn, "the texture-mapped surface's polygon file name");
    s.texture_map = file_name(scn, "the texture map file name");
    const std::string of = " of texture-mapped surface '" + s.polygon_file.name + "'";
    const Token scale = scn.take("the scale" + of);
    try {
        s.placement.scale = number_from(scn.source(), scale, "the scale" + of);
    } catch (const InputError& e) {
        // A number in the polygon file's place is most likely a smooth-shade field.
        if (!parse_double(s.polygon_file.name)) {
            throw;
        }
        throw InputError(e.where(), e.message() +
                                        " (a texture-mapped surface has no smooth-shade field, "
                                        "even with -Po or -Pt)");
    }
    if (s.placement.scale == 0.0) {
        throw InputError(location_of(scn.source(), scale), "the scale" + of + " must not be 0");
    }
    s.placement.translation = scn.coordinates("the translation");
    s.placement.rotation_degrees = scn.triple("the rotation about");
    read_grid_size(scn, s);
    return s;
}

void trace_surface(const ScnTexturedSurface& s, Diagnostics& diagnostics) {
    if (!diagnostics.tracing()) {
        return;
    }
    const SurfacePlacement& p = s.placement;
    diagnostics.trace(fmt::format(
        "{}: texture-mapped surface '{}' texture map '{}' attribute {} scale {} translation {} "
        "rotation {} grid {} x {}",
        s.where.to_string(), s.polygon_file.name, s.texture_map.name, s.attribute_number, p.scale,
        show_point(p.translation.x, p.translation.y, p.translation.z),
        show_point(p.rotation_degrees.x, p.rotation_degrees.y, p.rotation_degrees.z), s.rows,
        s.columns));
}

}  // namespace

void read_textured_surfaces(ItemStream& scn, ScnFile& scene, Diagnostics& diagnostics) {
    const std::int64_t count =
        scn.count("the texture-mapped surface count (-V)", kMaxTexturedSurfaces);
    scn.end_item();
    for (std::int64_t k = 0; k < count; ++k) {
        ScnTexturedSurface s = read_textured_surface(scn);
        scn.end_item();
        trace_surface(s, diagnostics);
        scene.textured_surfaces.push_back(std::move(s));
    }
    DollarLine line;
    LinesLeftOver left;
    while (scn.take_line(line)) {
        left.add(line.line);
    }
    left.warn(scn.source(), "texture-mapped surfaces", "", diagnostics);
}

}  // namespace rt
