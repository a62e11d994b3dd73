#include "support/hand_readers.h"

#include <bit>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <sstream>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt::test {

namespace {

// The next blank-separated word of a PPM header or a plain PPM body, skipping '#' comments.
std::string next_word(const std::string& text, std::size_t& at) {
    while (at < text.size()) {
        if (text[at] == '#') {
            while (at < text.size() && text[at] != '\n') {
                ++at;
            }
        } else if (std::isspace(static_cast<unsigned char>(text[at])) != 0) {
            ++at;
        } else {
            break;
        }
    }
    const std::size_t start = at;
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])) == 0) {
        ++at;
    }
    return text.substr(start, at - start);
}

int next_number(const std::string& text, std::size_t& at) {
    const std::string word = next_word(text, at);
    if (word.empty() || word.find_first_not_of("0123456789") != std::string::npos) {
        ADD_FAILURE() << "PPM: expected a number, found '" << word << "'";
        return -1;
    }
    return std::stoi(word);
}

float little_endian_float(const std::string& bytes, std::size_t at) {
    std::uint32_t bits = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        bits |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
    }
    return std::bit_cast<float>(bits);
}

}  // namespace

Image8 parse_ppm(const std::string& bytes) {
    std::size_t at = 0;
    const std::string magic = next_word(bytes, at);
    const int width = next_number(bytes, at);
    const int height = next_number(bytes, at);
    const int maxval = next_number(bytes, at);
    if ((magic != "P3" && magic != "P6") || width < 1 || height < 1 || maxval != 255) {
        ADD_FAILURE() << "PPM: expected P3 or P6 with maxval 255, found " << magic << " " << width
                      << " x " << height << " maxval " << maxval;
        return {};
    }
    Image8 image{width, height, {}};
    const std::size_t count = image.pixel_count() * 3;
    if (magic == "P6") {
        ++at;  // the single blank after maxval
        if (bytes.size() - at != count) {
            ADD_FAILURE() << "P6: expected " << count << " bytes of pixels, found "
                          << bytes.size() - at;
            return {};
        }
        image.rgb.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.end());
        return image;
    }
    for (std::size_t k = 0; k < count; ++k) {
        const int v = next_number(bytes, at);
        if (v < 0 || v > 255) {
            ADD_FAILURE() << "P3: sample " << k << " is " << v;
            return {};
        }
        image.rgb.push_back(static_cast<std::uint8_t>(v));
    }
    EXPECT_TRUE(next_word(bytes, at).empty()) << "P3: words after the last sample";
    return image;
}

const std::array<double, 3>& GroPixels::at(int x, int y) const {
    const std::size_t width = static_cast<std::size_t>(right - left) + 1;
    return pixels.at(static_cast<std::size_t>(y - top) * width +
                     static_cast<std::size_t>(x - left));
}

GroPixels parse_gro(const std::filesystem::path& path) {
    const std::string bytes = read_text(path);
    GroPixels gro;
    std::size_t at = 0;
    bool first = true;
    for (;;) {
        const std::size_t end = bytes.find('\n', at);
        if (end == std::string::npos) {
            ADD_FAILURE() << path << ": no 'end' line";
            return {};
        }
        const std::string line = bytes.substr(at, end - at);
        at = end + 1;
        if (first) {
            EXPECT_EQ(line, "GRO rt 1") << path;
            first = false;
            continue;
        }
        if (line == "end") {
            break;
        }
        const std::size_t space = line.find(' ');
        gro.header[line.substr(0, space)] =
            space == std::string::npos ? "" : line.substr(space + 1);
    }
    std::istringstream window(gro.header["window"]);
    window >> gro.left >> gro.top >> gro.right >> gro.bottom;
    EXPECT_EQ(gro.header["pixels"], "rgb-float32-le") << path;
    const std::size_t count = static_cast<std::size_t>(gro.right - gro.left + 1) *
                              static_cast<std::size_t>(gro.bottom - gro.top + 1);
    if (!window || bytes.size() - at != count * 12) {
        ADD_FAILURE() << path << ": expected " << count << " pixels of 12 bytes after the header";
        return {};
    }
    for (std::size_t k = 0; k < count; ++k, at += 12) {
        gro.pixels.push_back({little_endian_float(bytes, at), little_endian_float(bytes, at + 4),
                              little_endian_float(bytes, at + 8)});
    }
    return gro;
}

}  // namespace rt::test
