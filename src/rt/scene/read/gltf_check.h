// Assimp 5.2 parses a .gltf file's JSON, or a .glb file's JSON chunk, to decide whether it can
// read the file at all: JSON it cannot parse, or a binary header it does not take, ends in "No
// suitable reader found". It trusts the JSON chunk's length, reserving that much memory first (a
// 4 GB claim took 4.2 GB and 30 s before that message), and its recursive parser overflows the
// stack on arrays nested 300,000 deep (a 600 KB file). These checks name what is wrong first; the
// glTF schema is left to Assimp.
#pragma once

#include <filesystem>
#include <string>

namespace rt {

/// Checks that a .gltf file is one JSON object, as Assimp's parser reads JSON. Throws InputError
/// "name:line: expected ..., found ..." at the first fault, the end of the file included, or for
/// arrays and objects nested more than 1000 deep.
void check_gltf(const std::filesystem::path& path, const std::string& name);

/// Checks a .glb file's 12-byte header (magic "glTF", version 2 or 1, a length the file holds),
/// the JSON chunk's header after it (its type, a length within the file), then the chunk's JSON
/// as check_gltf does. Throws InputError "name: ..." (a JSON fault names its line in the chunk).
void check_glb(const std::filesystem::path& path, const std::string& name);

}  // namespace rt
