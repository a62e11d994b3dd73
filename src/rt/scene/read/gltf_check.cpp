#include "rt/scene/read/gltf_check.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>

#include "rt/core/error.h"
#include "rt/scene/read/gltf_json_check.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::uint32_t little_endian(const unsigned char* b) {
    return static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
           (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}

// Four bytes of a header as text, those that are not printable as \xNN: 'BIN\x00'.
std::string shown(const unsigned char* b) {
    std::string out = "'";
    for (int i = 0; i < 4; ++i) {
        out += b[i] >= 0x20 && b[i] < 0x7f ? std::string(1, static_cast<char>(b[i]))
                                           : fmt::format("\\x{:02x}", b[i]);
    }
    return out + "'";
}

constexpr std::uintmax_t kGlbHeaderBytes = 12;
constexpr std::uintmax_t kGlbChunkHeaderBytes = 8;

// The 12-byte header: magic, version, length.
void check_glb_header(const unsigned char* head, std::uintmax_t size, const std::string& name) {
    if (size < kGlbHeaderBytes) {
        throw InputError({name, 0, 0},
                         fmt::format("expected a binary glTF of at least 12 bytes (its header), "
                                     "found {} bytes",
                                     size));
    }
    if (std::memcmp(head, "glTF", 4) != 0) {
        throw expected_found({name, 0, 0}, "'glTF' to start a binary glTF", shown(head));
    }
    const std::uint32_t version = little_endian(head + 4);
    if (version != 2 && version != 1) {
        throw expected_found({name, 0, 0}, "binary glTF version 2 (or 1)",
                             fmt::format("version {}", version));
    }
    // A length short of the file's Assimp reads (the bytes after it unused); a longer one is a
    // file cut short.
    if (const std::uint32_t length = little_endian(head + 8); length > size) {
        throw InputError({name, 0, 0},
                         fmt::format("the header gives the file's length as {} bytes, but it has "
                                     "{} (the file is truncated or its header is wrong)",
                                     length, size));
    }
}

// The JSON chunk's header (version 1: the JSON's length and format, at the same places); returns
// the JSON's length.
std::uint32_t check_glb_json_header(const unsigned char* head, std::uintmax_t size,
                                    const std::string& name) {
    if (size < kGlbHeaderBytes + kGlbChunkHeaderBytes) {
        throw InputError({name, 0, 0},
                         fmt::format("expected the JSON chunk's 8-byte header after the file's, "
                                     "found {} bytes",
                                     size - kGlbHeaderBytes));
    }
    const std::uint32_t length = little_endian(head + 12);
    if (little_endian(head + 4) == 2 && std::memcmp(head + 16, "JSON", 4) != 0) {
        throw expected_found({name, 0, 0}, "a first chunk of type 'JSON'", shown(head + 16));
    }
    if (little_endian(head + 4) == 1 && little_endian(head + 16) != 0) {
        throw expected_found({name, 0, 0}, "scene format 0 (JSON) in a version 1 binary glTF",
                             fmt::format("{}", little_endian(head + 16)));
    }
    const std::uintmax_t room = size - kGlbHeaderBytes - kGlbChunkHeaderBytes;
    if (length > room) {
        throw InputError({name, 0, 0},
                         fmt::format("the JSON chunk's header gives its length as {} bytes, but {} "
                                     "follow it (the file is truncated or its header is wrong)",
                                     length, room));
    }
    return length;
}

}  // namespace

void check_gltf(const std::filesystem::path& path, const std::string& name) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 4> magic{};
    in.read(magic.data(), magic.size());
    if (in && std::memcmp(magic.data(), "glTF", 4) == 0) {
        throw expected_found({name, 0, 0}, "JSON",
                             "a binary glTF (Assimp reads one only under a name ending in .glb)");
    }
    in.clear();
    in.seekg(0);
    check_gltf_json(in, std::filesystem::file_size(path), name, false);
}

void check_glb(const std::filesystem::path& path, const std::string& name) {
    std::ifstream in(path, std::ios::binary);
    std::array<unsigned char, kGlbHeaderBytes + kGlbChunkHeaderBytes> head{};
    in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
    const std::uintmax_t size = std::filesystem::file_size(path);
    check_glb_header(head.data(), size, name);
    const std::uint32_t length = check_glb_json_header(head.data(), size, name);
    check_gltf_json(in, length, name, true);
}

}  // namespace rt
