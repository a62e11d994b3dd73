#include "rt/scene/read/scn_entities.h"

#include <algorithm>

#include "rt/core/text.h"
#include "rt/scene/read/counted_lines.h"
#include "rt/scene/read/reader_limits.h"
#include "rt/scene/read/scn_textures.h"

#include <fmt/format.h>

namespace rt {

namespace {

// A number where the file name was, without -Po/-Pt, is most likely a smooth-shade field.
double read_scale(ItemStream& scn, const ScnSurface& s, const ReaderDialect& dialect) {
    const std::string what = "the scale of optical surface '" + s.surface.file + "'";
    const Token token = scn.take(what);
    double scale = 0.0;
    try {
        scale = number_from(scn.source(), token, what);
    } catch (const InputError& e) {
        if (dialect.smooth_shade_field || !parse_double(s.surface.file)) {
            throw;
        }
        throw InputError(e.where(), e.message() +
                                        " (a fourth number before the file name is the "
                                        "smooth-shade field, read only with -Po or -Pt)");
    }
    if (scale == 0.0) {
        throw InputError(location_of(scn.source(), token),
                         "the scale of optical surface '" + s.surface.file + "' must not be 0");
    }
    return scale;
}

void read_surface_fields(ItemStream& scn, const ReaderDialect& dialect, ScnSurface& s) {
    OpticalSurface& o = s.surface;
    const Token first = scn.take("the optical surface's index number");
    o.where = location_of(scn.source(), first);
    integer_from(scn.source(), first, "the optical surface's index number");  // read, ignored
    o.attribute_number = static_cast<long>(scn.integer("the optical surface's attribute number"));
    o.filetype =
        static_cast<int>(integer_in(scn.source(), scn.take("the filetype"), "the filetype", 0, 3));
    if (dialect.smooth_shade_field) {
        const std::string what = "the smooth-shade field of -Po/-Pt";
        o.smooth_shaded = integer_in(scn.source(), scn.take(what), what, 0, 1) == 1;
    }
    o.file = std::string(scn.take("the optical surface file name").text);
    s.placement.scale = read_scale(scn, s, dialect);
    // A translation beyond the coordinate range would place every vertex outside it.
    s.placement.translation = scn.coordinates("the translation");
    s.placement.rotation_degrees = scn.triple("the rotation about");
    if (o.filetype == 1 && o.smooth_shaded) {
        throw InputError(o.where, "optical surface '" + o.file +
                                      "' has filetype 1 (Phigs+), whose polygons cannot be "
                                      "smooth-shaded");
    }
}

void trace_surface(ItemStream& scn, const ScnSurface& s, Diagnostics& diagnostics) {
    if (!diagnostics.tracing()) {
        return;
    }
    const OpticalSurface& o = s.surface;
    const SurfacePlacement& p = s.placement;
    diagnostics.trace(fmt::format(
        "{}: entity {}: optical surface '{}' filetype {} attribute {} smooth {} scale {} "
        "translation {} rotation {}",
        scn.source().at(o.where.line).to_string(), o.entity, o.file, o.filetype, o.attribute_number,
        o.smooth_shaded ? 1 : 0, p.scale,
        show_point(p.translation.x, p.translation.y, p.translation.z),
        show_point(p.rotation_degrees.x, p.rotation_degrees.y, p.rotation_degrees.z)));
}

}  // namespace

void read_entities(ItemStream& scn, const ReaderDialect& dialect, ScnFile& scene,
                   Diagnostics& diagnostics) {
    const std::int64_t entities = scn.count("the entity count", kMaxEntities);
    scn.end_item();
    for (std::int64_t e = 1; e <= entities; ++e) {
        const std::string what = fmt::format("the optical surface count of entity {}", e);
        const std::int64_t surfaces = scn.count(what, kMaxSurfacesPerEntity);
        scn.end_item();
        for (std::int64_t k = 0; k < surfaces; ++k) {
            ScnSurface s;
            s.surface.entity = static_cast<int>(e);
            read_surface_fields(scn, dialect, s);
            scn.end_item();
            trace_surface(scn, s, diagnostics);
            scene.surfaces.push_back(std::move(s));
        }
    }
}

void read_after_entities(ItemStream& scn, const ReaderDialect& dialect, ScnFile& scene,
                         Diagnostics& diagnostics) {
    if (dialect.textures) {
        read_textured_surfaces(scn, scene, diagnostics);
        return;
    }
    DollarLine line;
    LinesLeftOver left;
    while (scn.take_line(line)) {
        left.add(line.line);
    }
    left.warn(scn.source(), "entities", ": texture-mapped surfaces are read only with -V",
              diagnostics);
}

}  // namespace rt
