#include "rt/image/image_writer.h"

#include <cctype>
#include <string>

#include "rt/core/error.h"
#include "rt/image/display_mapping.h"
#include "rt/image/gro_format.h"
#include "rt/image/png_format.h"
#include "rt/image/ppm_format.h"

namespace rt {

ImageFormat image_format_for(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (extension == ".gro") {
        return ImageFormat::Gro;
    }
    if (extension == ".png") {
        return ImageFormat::Png;
    }
    if (extension == ".ppm") {
        return ImageFormat::Ppm;
    }
    const std::string known = " (known: .gro, .png, .ppm)";
    if (extension.empty()) {
        throw UsageError("cannot write '" + path.string() + "': no image format extension" + known);
    }
    throw UsageError("cannot write '" + path.string() + "': unknown image format '" +
                     path.extension().string() + "'" + known);
}

void write_image(const Film& film, const std::filesystem::path& path) {
    switch (image_format_for(path)) {
        case ImageFormat::Gro:
            write_gro(film, path);
            return;
        case ImageFormat::Png:
            write_png(to_display(film), path);
            return;
        case ImageFormat::Ppm:
            write_ppm(to_display(film), path);
            return;
    }
}

}  // namespace rt
