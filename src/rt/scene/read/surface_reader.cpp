#include "rt/scene/read/surface_reader.h"

#include "rt/scene/read/model_reader.h"
#include "rt/scene/read/phigs_reader.h"
#include "rt/scene/read/polygon_file_reader.h"
#include "rt/scene/read/prinz_reader.h"

namespace rt {

SurfaceMesh read_optical_surface(const std::filesystem::path& path, const OpticalSurface& surface,
                                 const ReaderDialect& dialect, Diagnostics& diagnostics) {
    if (surface.filetype == kModelFiletype) {
        return read_model_file(path, surface.file, surface.where, diagnostics);
    }
    const SourceText source =
        read_named_file(path, "optical surface file", surface.file, surface.where);
    switch (surface.filetype) {
        case 0:
            return read_polygon_file(source, dialect.marks, diagnostics);
        case 1:
            return read_phigs_file(source, diagnostics);
        case 2:
            return read_prinz_file(source, diagnostics);
        default:
            // The .scn reader accepts only 0 to 3.
            throw InputError(surface.where, "unknown filetype " + std::to_string(surface.filetype));
    }
}

}  // namespace rt
