#include "rt/image/png_format.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "rt/core/atomic_file.h"
#include "rt/core/error.h"

#include <png.h>

namespace rt {

namespace {

// png_image must be released on every path, including the throwing ones.
class PngImage {
public:
    PngImage() {
        std::memset(&image_, 0, sizeof image_);
        image_.version = PNG_IMAGE_VERSION;
    }
    ~PngImage() { png_image_free(&image_); }
    PngImage(const PngImage&) = delete;
    PngImage& operator=(const PngImage&) = delete;

    png_image* get() { return &image_; }
    png_image* operator->() { return &image_; }
    std::string message() const { return image_.message; }

private:
    png_image image_{};
};

}  // namespace

std::vector<std::uint8_t> encode_png(const Image8& image) {
    if (image.width < 1 || image.height < 1 || image.rgb.size() != image.pixel_count() * 3) {
        throw Error("cannot encode an empty or inconsistent image as PNG");
    }
    PngImage png;
    png->width = static_cast<png_uint_32>(image.width);
    png->height = static_cast<png_uint_32>(image.height);
    png->format = PNG_FORMAT_RGB;
    // Room for the largest PNG the image can make, so that it is compressed once: asked for its
    // size first, libpng compresses the whole image to measure it (half of twocubes4's 20 ms
    // write).
    png_alloc_size_t size = PNG_IMAGE_PNG_SIZE_MAX(*png.get());
    std::vector<std::uint8_t> bytes(size);
    if (png_image_write_to_memory(png.get(), bytes.data(), &size, 0, image.rgb.data(), 0,
                                  nullptr) == 0) {
        throw Error("cannot encode PNG: " + png.message());
    }
    bytes.resize(size);
    return bytes;
}

void write_png(const Image8& image, const std::filesystem::path& path) {
    std::vector<std::uint8_t> bytes;
    try {
        bytes = encode_png(image);
    } catch (const Error& e) {
        throw Error("cannot write " + path.string() + ": " + e.what());
    }
    write_file_atomically(path, [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
    });
}

Image8 read_png(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw IoError("cannot open " + file + ": " +
                      (ec ? ec.message() : std::string("not a regular file")));
    }
    PngImage png;
    if (png_image_begin_read_from_file(png.get(), file.c_str()) == 0) {
        throw expected_found({file, 0, 0}, "a PNG picture", "'" + png.message() + "'");
    }
    // Checked before the pixel buffer is allocated.
    if (png->width < 1 || png->height < 1 || png->width > kMaxImageSide ||
        png->height > kMaxImageSide) {
        throw expected_found({file, 0, 0},
                             "a PNG of at most " + std::to_string(kMaxImageSide) + " pixels a side",
                             std::to_string(png->width) + " x " + std::to_string(png->height));
    }
    png->format = PNG_FORMAT_RGB;
    // Without a gAMA or sRGB chunk libpng takes 16-bit samples as linear light and gamma-encodes
    // them on the way to 8 bits (a sample of 25 * 257 read as 88); the PNG specification's plain
    // scaling (v / 257) is what a picture file without colour information means to us.
    png->flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
    Image8 image;
    image.width = static_cast<int>(png->width);
    image.height = static_cast<int>(png->height);
    image.rgb.resize(image.pixel_count() * 3);
    if (png_image_finish_read(png.get(), nullptr, image.rgb.data(), 0, nullptr) == 0) {
        throw expected_found({file, 0, 0}, "a readable PNG picture", "'" + png.message() + "'");
    }
    return image;
}

}  // namespace rt
