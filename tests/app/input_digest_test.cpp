// The digest a .gro records for --resume, against FNV-1a worked out here byte by byte over what
// input_digest.h says it covers: files small and larger than any block a reader takes, empty and
// missing ones (the floor of --model names no file), and texture pictures.
#include "rt/app/input_digest.h"

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt {
namespace {

struct ByteByByteFnv {
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    void add(std::string_view bytes) {
        for (const char c : bytes) {
            hash ^= static_cast<unsigned char>(c);
            hash *= 0x100000001b3ULL;
        }
    }
    void add_number(std::uint64_t n) {
        std::string bytes(sizeof n, '\0');
        std::memcpy(bytes.data(), &n, sizeof n);  // as the number is stored
        add(bytes);
    }
};

std::string random_bytes(std::size_t size, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::string bytes(size, '\0');
    for (char& c : bytes) {
        c = static_cast<char>(random() & 0xffu);
    }
    return bytes;
}

TEST(InputDigest, IsFnv1aOverNamesSizesBytesAndPictures) {
    const test::TempDir dir;
    const std::vector<std::string> contents = {"attributes\n$ 1\n", "", random_bytes(3'000'017, 5),
                                               random_bytes(1 << 20, 6)};
    Scene scene;
    ByteByByteFnv expected;
    for (std::size_t k = 0; k < contents.size(); ++k) {
        const std::string name = dir.write(fmt::format("file{}", k), contents[k]).string();
        scene.source_files.push_back(name);
        expected.add_number(name.size());
        expected.add(name);
        expected.add_number(contents[k].size());
        expected.add(contents[k]);
    }
    const std::string missing = (dir.path() / "no such file").string();
    scene.source_files.push_back(missing);
    expected.add_number(missing.size());
    expected.add(missing);
    expected.add_number(0);
    TextureImage picture;
    picture.width = 2;
    picture.height = 1;
    picture.rgb = {10, 20, 30, 40, 50, 60};
    scene.texture_images.push_back(picture);
    expected.add_number(2);
    expected.add_number(1);
    expected.add(std::string_view(reinterpret_cast<const char*>(picture.rgb.data()),
                                  picture.rgb.size() * sizeof(picture.rgb[0])));
    EXPECT_EQ(input_digest(scene), fmt::format("fnv1a64:{:016x}", expected.hash));
}

}  // namespace
}  // namespace rt
