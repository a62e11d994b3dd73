#include "rt/image/image_writer.h"

#include <cctype>
#include <string>

#include "rt/core/error.h"
#include "rt/image/display_mapping.h"
#include "rt/image/exr_format.h"
#include "rt/image/gro_format.h"
#include "rt/image/png_format.h"
#include "rt/image/ppm_format.h"

namespace rt {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return extension;
}

}  // namespace

ImageFormat image_format_for(const std::filesystem::path& path) {
    const std::string extension = lower_extension(path);
    if (extension == ".gro") {
        return ImageFormat::Gro;
    }
    if (extension == ".exr") {
        return ImageFormat::Exr;
    }
    if (extension == ".png") {
        return ImageFormat::Png;
    }
    if (extension == ".ppm") {
        return ImageFormat::Ppm;
    }
    const std::string known = " (known: .gro, .exr, .png, .ppm)";
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
        case ImageFormat::Exr:
            write_exr(film, path);
            return;
        case ImageFormat::Png:
            write_png(to_display(film), path);
            return;
        case ImageFormat::Ppm:
            write_ppm(to_display(film), path);
            return;
    }
}

Film read_linear_image(const std::filesystem::path& path) {
    return lower_extension(path) == ".exr" ? read_exr(path) : read_gro(path);
}

}  // namespace rt
