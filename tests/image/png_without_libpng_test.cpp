// rt's PNG writer checked by a decoder that does not use libpng: the chunks, zlib's inflate and the
// five row filters undone here from the PNG specification. It reads what rt writes (8-bit RGB,
// not interlaced) and nothing else; it is checked itself on tests/data/png/rgb8.png, which another
// encoder made.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "rt/image/png_format.h"

#include <gtest/gtest.h>

#include "support/hand_readers.h"
#include "support/temp_dir.h"
#include <zlib.h>

namespace rt::test {
namespace {

std::uint32_t big_endian(const std::vector<std::uint8_t>& bytes, std::size_t at) {
    return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
           (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
}

int paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a);
    const int pb = std::abs(p - b);
    const int pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) {
        return a;
    }
    return pb <= pc ? b : c;
}

// Undoes the scanline filters in place; each row is a filter byte then 3 * width bytes.
std::vector<std::uint8_t> unfilter(const std::vector<std::uint8_t>& data, int width, int height) {
    const std::size_t stride = static_cast<std::size_t>(width) * 3;
    std::vector<std::uint8_t> pixels(stride * static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
        const int kind = data[y * (stride + 1)];
        EXPECT_LE(kind, 4) << "row " << y;
        for (std::size_t i = 0; i < stride; ++i) {
            const int a = i >= 3 ? pixels[y * stride + i - 3] : 0;
            const int b = y > 0 ? pixels[(y - 1) * stride + i] : 0;
            const int c = y > 0 && i >= 3 ? pixels[(y - 1) * stride + i - 3] : 0;
            const std::array<int, 5> predictor{0, a, b, (a + b) / 2, paeth(a, b, c)};
            const int raw = data[y * (stride + 1) + 1 + i];
            pixels[y * stride + i] = static_cast<std::uint8_t>(raw + predictor.at(kind));
        }
    }
    return pixels;
}

Image8 decode_rgb8_png(const std::vector<std::uint8_t>& bytes) {
    const std::array<std::uint8_t, 8> signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || !std::equal(signature.begin(), signature.end(), bytes.begin())) {
        ADD_FAILURE() << "no PNG signature";
        return {};
    }
    Image8 image;
    std::vector<std::uint8_t> compressed;
    bool ended = false;
    for (std::size_t at = 8; at + 12 <= bytes.size() && !ended;) {
        const std::uint32_t length = big_endian(bytes, at);
        const std::string kind(bytes.begin() + static_cast<std::ptrdiff_t>(at + 4),
                               bytes.begin() + static_cast<std::ptrdiff_t>(at + 8));
        const std::size_t data = at + 8;
        if (data + length + 4 > bytes.size()) {
            ADD_FAILURE() << "chunk " << kind << " runs past the end";
            return {};
        }
        const std::uint32_t crc = static_cast<std::uint32_t>(
            crc32(0, bytes.data() + at + 4, static_cast<uInt>(length + 4)));
        EXPECT_EQ(crc, big_endian(bytes, data + length)) << "CRC of " << kind;
        if (kind == "IHDR") {
            image.width = static_cast<int>(big_endian(bytes, data));
            image.height = static_cast<int>(big_endian(bytes, data + 4));
            // depth 8, colour type 2 (RGB), compression 0, filter method 0, not interlaced
            EXPECT_EQ(
                std::vector<std::uint8_t>(bytes.begin() + static_cast<std::ptrdiff_t>(data + 8),
                                          bytes.begin() + static_cast<std::ptrdiff_t>(data + 13)),
                (std::vector<std::uint8_t>{8, 2, 0, 0, 0}));
        } else if (kind == "IDAT") {
            compressed.insert(compressed.end(), bytes.begin() + static_cast<std::ptrdiff_t>(data),
                              bytes.begin() + static_cast<std::ptrdiff_t>(data + length));
        } else if (kind == "IEND") {
            ended = true;
        }
        at = data + length + 4;
    }
    EXPECT_TRUE(ended) << "no IEND";
    uLongf size = static_cast<uLongf>(image.height) * (1 + 3 * static_cast<uLongf>(image.width));
    std::vector<std::uint8_t> filtered(size);
    const int status = uncompress(filtered.data(), &size, compressed.data(),
                                  static_cast<uLong>(compressed.size()));
    if (status != Z_OK || size != filtered.size()) {
        ADD_FAILURE() << "inflate: status " << status << ", " << size << " bytes";
        return {};
    }
    image.rgb = unfilter(filtered, image.width, image.height);
    return image;
}

std::vector<std::uint8_t> bytes_of(const std::filesystem::path& path) {
    const std::string text = read_text(path);
    return {text.begin(), text.end()};
}

TEST(PngWithoutLibpng, TheDecoderReadsAnotherEncodersFile) {
    const std::filesystem::path folder = source_dir() / "tests/data/png";
    EXPECT_EQ(decode_rgb8_png(bytes_of(folder / "rgb8.png")),
              parse_ppm(read_text(folder / "source.ppm")));
}

// A picture that makes libpng's adaptive filtering choose among its filters: smooth ramps, noise
// and flat runs.
Image8 varied_picture() {
    Image8 image{67, 41, {}};
    std::uint32_t noise = 12345;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            noise = noise * 1664525U + 1013904223U;
            const bool noisy = (y / 8) % 2 == 1;
            image.rgb.push_back(static_cast<std::uint8_t>(noisy ? noise >> 24 : x * 3));
            image.rgb.push_back(static_cast<std::uint8_t>(y * 6 + x));
            image.rgb.push_back(static_cast<std::uint8_t>(x < 30 ? 200 : (x * y) & 0xff));
        }
    }
    return image;
}

TEST(PngWithoutLibpng, ReadsWhatRtWrites) {
    const TempDir dir;
    const Image8 picture = varied_picture();
    write_png(picture, dir.path() / "varied.png");
    EXPECT_EQ(decode_rgb8_png(bytes_of(dir.path() / "varied.png")), picture);
    const Image8 source = parse_ppm(read_text(source_dir() / "tests/data/png/source.ppm"));
    EXPECT_EQ(decode_rgb8_png(encode_png(source)), source);
}

// The golden references were written by rt (their rows use all five filter types); the golden
// tests read them with libpng, which must see what this decoder sees.
TEST(PngWithoutLibpng, AgreesWithTheReaderOnAGoldenReference) {
    const std::filesystem::path golden = source_dir() / "tests/data/golden/twocubes.png";
    const Image8 decoded = decode_rgb8_png(bytes_of(golden));
    EXPECT_EQ(decoded.width, 512);
    EXPECT_EQ(decoded, read_png(golden));
}

}  // namespace
}  // namespace rt::test
