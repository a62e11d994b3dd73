#include "rt/app/input_digest.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string_view>

#include <fmt/format.h>

namespace rt {

namespace {

class Fnv1a64 {
public:
    void add(std::string_view bytes) {
        for (const char c : bytes) {
            hash_ ^= static_cast<unsigned char>(c);
            hash_ *= 0x100000001b3ULL;
        }
    }
    void add_number(std::uint64_t n) {
        add(std::string_view(reinterpret_cast<const char*>(&n), sizeof n));
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace

std::string input_digest(const Scene& scene) {
    Fnv1a64 hash;
    for (const std::string& name : scene.source_files) {
        hash.add_number(name.size());
        hash.add(name);
        // Names that are no file (the floor of --model) stand for what the program builds.
        std::ifstream in(name, std::ios::binary);
        const std::string bytes = in ? std::string(std::istreambuf_iterator<char>(in), {}) : "";
        hash.add_number(bytes.size());
        hash.add(bytes);
    }
    for (const TextureImage& picture : scene.texture_images) {
        hash.add_number(static_cast<std::uint64_t>(picture.width));
        hash.add_number(static_cast<std::uint64_t>(picture.height));
        hash.add(std::string_view(reinterpret_cast<const char*>(picture.rgb.data()),
                                  picture.rgb.size() * sizeof(picture.rgb[0])));
    }
    return fmt::format("fnv1a64:{:016x}", hash.value());
}

}  // namespace rt
