#include "rt/image/png_format.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
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

namespace {

std::uint32_t big_endian(const unsigned char* bytes) {
    return (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
           (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]};
}

struct ChunkWalk {
    int bits_per_pixel = 0;              ///< from IHDR: bit depth times samples a pixel
    std::uint64_t compressed_bytes = 0;  ///< the IDAT chunks' data present in the file
};

// Walks the chunks after the signature by their lengths, reading only IHDR's fields. A chunk cut
// short by the end of the file counts for the bytes it has.
ChunkWalk walk_chunks(const std::filesystem::path& path) {
    ChunkWalk walk;
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    std::uint64_t at = 8;
    unsigned char head[8];
    while (!ec && at + 8 <= size && in.seekg(static_cast<std::streamoff>(at)) &&
           in.read(reinterpret_cast<char*>(head), 8)) {
        const std::uint64_t length = big_endian(head);
        const std::string type(reinterpret_cast<const char*>(head + 4), 4);
        at += 8;
        if (type == "IHDR" && length == 13) {
            unsigned char fields[13];
            if (!in.read(reinterpret_cast<char*>(fields), 13)) {
                break;
            }
            // Samples a pixel by colour type: grey, -, RGB, palette index, grey+alpha, -, RGBA.
            constexpr int kSamples[7] = {1, 0, 3, 1, 2, 0, 4};
            walk.bits_per_pixel = fields[9] < 7 ? kSamples[fields[9]] * fields[8] : 0;
        } else if (type == "IDAT") {
            walk.compressed_bytes += std::min(length, size - at);
        } else if (type == "IEND") {
            break;
        }
        at += length + 4;  // the data and the CRC
    }
    return walk;
}

// Opens the PNG with libpng and checks what its header claims, before anything is allocated.
PngHeader begin_read(PngImage& png, const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw IoError("cannot open " + file + ": " +
                      (ec ? ec.message() : std::string("not a regular file")));
    }
    if (png_image_begin_read_from_file(png.get(), file.c_str()) == 0) {
        throw expected_found({file, 0, 0}, "a PNG picture", "'" + png.message() + "'");
    }
    if (png->width < 1 || png->height < 1 || png->width > kMaxImageSide ||
        png->height > kMaxImageSide) {
        throw expected_found({file, 0, 0},
                             "a PNG of at most " + std::to_string(kMaxImageSide) + " pixels a side",
                             std::to_string(png->width) + " x " + std::to_string(png->height));
    }
    PngHeader header;
    header.width = static_cast<int>(png->width);
    header.height = static_cast<int>(png->height);
    const ChunkWalk walk = walk_chunks(path);
    header.compressed_bytes = walk.compressed_bytes;
    // The pixel rows deflate must unpack, filter bytes and interlacing aside: a lower bound.
    const std::uint64_t rows = static_cast<std::uint64_t>(header.width) *
                               static_cast<std::uint64_t>(header.height) *
                               static_cast<std::uint64_t>(walk.bits_per_pixel) / 8;
    if (rows > kMaxDeflateRatio * header.compressed_bytes) {
        const std::string size =
            std::to_string(header.width) + " x " + std::to_string(header.height);
        throw expected_found(
            {file, 0, 0},
            "a PNG picture whose compressed data (" + std::to_string(header.compressed_bytes) +
                " bytes) can hold its " + size + " pixels",
            std::to_string(rows) +
                " bytes of pixel rows to unpack from them (deflate unpacks at most " +
                std::to_string(kMaxDeflateRatio) + " bytes from each)");
    }
    return header;
}

}  // namespace

PngHeader read_png_header(const std::filesystem::path& path) {
    PngImage png;
    return begin_read(png, path);
}

Image8 read_png(const std::filesystem::path& path) {
    const std::string file = path.string();
    PngImage png;
    const PngHeader header = begin_read(png, path);
    png->format = PNG_FORMAT_RGB;
    // Without a gAMA or sRGB chunk libpng takes 16-bit samples as linear light and gamma-encodes
    // them on the way to 8 bits (a sample of 25 * 257 read as 88); the PNG specification's plain
    // scaling (v / 257) is what a picture file without colour information means to us.
    png->flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
    Image8 image;
    image.width = header.width;
    image.height = header.height;
    image.rgb.resize(image.pixel_count() * 3);
    if (png_image_finish_read(png.get(), nullptr, image.rgb.data(), 0, nullptr) == 0) {
        throw expected_found({file, 0, 0}, "a readable PNG picture", "'" + png.message() + "'");
    }
    return image;
}

}  // namespace rt
