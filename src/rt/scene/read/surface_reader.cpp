#include "rt/scene/read/surface_reader.h"

#include "rt/scene/read/phigs_reader.h"
#include "rt/scene/read/polygon_file_reader.h"
#include "rt/scene/read/prinz_reader.h"

namespace rt {

SurfaceMesh read_optical_surface(const SourceText& source, int filetype,
                                 const ReaderDialect& dialect, Diagnostics& diagnostics) {
    switch (filetype) {
        case 0:
            return read_polygon_file(source, dialect.marks, diagnostics);
        case 1:
            return read_phigs_file(source, diagnostics);
        case 2:
            return read_prinz_file(source, diagnostics);
        default:
            // The .scn reader accepts only 0, 1 and 2.
            throw InputError(source.at(0), "unknown filetype " + std::to_string(filetype));
    }
}

}  // namespace rt
