// glTF files that Assimp 5.2 cannot parse ("No suitable reader found") are refused before it reads
// them, naming the fault's line; a .glb's headers are checked before Assimp trusts the JSON
// chunk's length. Good files still load.
#include "rt/scene/read/gltf_check.h"

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "model_files.h"
#include "model_reader_fixture.h"

namespace rt::test {
namespace {

TEST_F(ModelReader, GltfFilesLoadWithTheirBlanks) {
    EXPECT_EQ(read("m.gltf", triangle_gltf).polygons.size(), 1u);
    std::string crlf;
    for (const char c : triangle_gltf) {
        crlf += c == '\n' ? std::string("\r\n\t") : std::string(1, c);
    }
    EXPECT_EQ(read("m.gltf", crlf + "\n\n").polygons.size(), 1u);
    // Bytes above 127 are taken as they are, as Assimp's parser takes them (Latin-1 here).
    std::string latin = triangle_gltf;
    latin.insert(latin.find("\"scene\""), "\"extras\": {\"name\": \"caf\xe9\"},\n");
    EXPECT_EQ(read("m.gltf", latin).polygons.size(), 1u);
    EXPECT_EQ(read("m.glb", triangle_glb()).polygons.size(), 1u);
}

TEST_F(ModelReader, GltfJsonCutShortOrNotJsonIsRefusedAtItsLine) {
    // Cut after the "scenes" line (the file's line 4).
    const std::string cut = triangle_gltf.substr(0, triangle_gltf.find("\n\"nodes\"") + 1);
    EXPECT_EQ(error("m.gltf", cut),
              "m.gltf:4: expected a member name in quotes, found end of file");
    EXPECT_EQ(error("m.gltf", cut.substr(0, cut.size() - 2)),
              "m.gltf:4: expected ',' or '}' in an object, found end of file");
    EXPECT_EQ(error("m.gltf", cut.substr(0, cut.size() - 5)),
              "m.gltf:4: expected ',' or ']' in an array, found end of file");
    EXPECT_EQ(error("m.gltf", "{\"asset\": {\"version\": \"2.0\n\"}}"),
              "m.gltf:1: expected '\"' to end the string, found a line break");
    EXPECT_EQ(error("m.gltf", "{\"asset\": {\"version\": \"2.0\"},}"),
              "m.gltf:1: expected a member name in quotes, found '}'");
    EXPECT_EQ(error("m.gltf", "{\"asset\": {\"version\": 2.}}"),
              "m.gltf:1: expected a digit after the decimal point, found '}'");
    EXPECT_EQ(error("m.gltf", "{\n\"scene\": tru\n}"), "m.gltf:2: expected a value, found 'tru'");
    EXPECT_EQ(error("m.gltf", triangle_gltf + "}"),
              "m.gltf:11: expected the end of the file after the glTF object, found '}'");
    EXPECT_EQ(error("m.gltf", "[{\"asset\": {\"version\": \"2.0\"}}]"),
              "m.gltf:1: expected '{' to start the glTF object, found '['");
    EXPECT_EQ(error("m.gltf", ""),
              "m.gltf:1: expected '{' to start the glTF object, found end of file");
    EXPECT_EQ(error("m.gltf", "\xef\xbb\xbf" + triangle_gltf),
              "m.gltf:1: expected '{' to start the glTF object, found a UTF-8 byte order mark "
              "(Assimp's parser reads JSON without one)");
    EXPECT_EQ(error("m.gltf", triangle_glb()),
              "m.gltf: expected JSON, found a binary glTF (Assimp reads one only under a name "
              "ending in .glb)");
}

// RapidJSON refuses what a double cannot hold, and a lone UTF-16 high surrogate; Assimp said "No
// suitable reader found".
TEST_F(ModelReader, GltfNumbersBeyondADoubleAndHalfSurrogatesAreRefused) {
    EXPECT_EQ(error("m.gltf", "{\"asset\": {\"version\": \"2.0\"},\n\"extras\": [1, -1e400]}"),
              "m.gltf:2: expected a number within a double's range, found '-1e400'");
    EXPECT_EQ(
        error("m.gltf", "{\"asset\": {\"version\": \"2.0\", \"generator\": \"\\ud83d\"}}"),
        "m.gltf:1: expected '\\u' and a low surrogate (DC00 to DFFF) after a high one (D800 to "
        "DBFF), found '\"'");
    std::string largest = triangle_gltf;
    largest.insert(largest.find("\"scene\""),
                   "\"extras\": [1.7976931348623157e308, 1e-400, \"\\ud83d\\ude00\"],\n");
    EXPECT_EQ(read("m.gltf", largest).polygons.size(), 1u);
}

// Assimp's recursive parser crashed on arrays nested 300,000 deep (a 600 KB file).
TEST_F(ModelReader, GltfJsonNestedDeeperThan1000IsRefused) {
    std::string deep = triangle_gltf;
    deep.insert(deep.find("\"scene\""),
                "\"extras\": " + std::string(999, '[') + std::string(999, ']') + ",\n");
    EXPECT_EQ(read("m.gltf", deep).polygons.size(), 1u);  // 1000 deep with the object
    deep.insert(deep.find('['), 1, '[');
    deep.insert(deep.find(']'), 1, ']');
    EXPECT_EQ(error("m.gltf", deep),
              "m.gltf:3: the JSON's arrays and objects nest more than 1000 deep");
}

TEST_F(ModelReader, AGlbsHeadersMustHoldWhatTheyPromise) {
    const std::string glb = triangle_glb();
    const auto with = [&](std::size_t at, const std::string& bytes) {
        return std::string(glb).replace(at, bytes.size(), bytes);
    };
    EXPECT_EQ(error("m.glb", glb.substr(0, 8)),
              "m.glb: expected a binary glTF of at least 12 bytes (its header), found 8 bytes");
    EXPECT_EQ(error("m.glb", with(0, "glTf")),
              "m.glb: expected 'glTF' to start a binary glTF, found 'glTf'");
    EXPECT_EQ(error("m.glb", with(4, le32(3))),
              "m.glb: expected binary glTF version 2 (or 1), found version 3");
    EXPECT_EQ(error("m.glb", glb.substr(0, 200)),
              fmt::format("m.glb: the header gives the file's length as {} bytes, but it has 200 "
                          "(the file is truncated or its header is wrong)",
                          glb.size()));
    EXPECT_EQ(error("m.glb", with(8, le32(12)).substr(0, 16)),
              "m.glb: expected the JSON chunk's 8-byte header after the file's, found 4 bytes");
    EXPECT_EQ(error("m.glb", with(16, std::string("BIN\0", 4))),
              "m.glb: expected a first chunk of type 'JSON', found 'BIN\\x00'");
    // Assimp reserved the length first: 4 GB, for 30 s, before "No suitable reader found".
    EXPECT_EQ(error("m.glb", with(12, le32(0xfffffff0))),
              fmt::format("m.glb: the JSON chunk's header gives its length as 4294967280 bytes, "
                          "but {} follow it (the file is truncated or its header is wrong)",
                          glb.size() - 20));
    // A fault in the JSON chunk names its line in the chunk.
    EXPECT_EQ(error("m.glb", with(20 + triangle_gltf.find("\"scene\""), "'")),
              "m.glb: line 3 of the JSON chunk: expected a member name in quotes, found \''\'");
    // A length short of the file's Assimp reads, the bytes after it unused.
    EXPECT_EQ(read("m.glb", glb + std::string(4, '\0')).polygons.size(), 1u);
}

}  // namespace
}  // namespace rt::test
