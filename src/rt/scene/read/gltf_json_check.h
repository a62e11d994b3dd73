// The JSON of a glTF file, walked as Assimp 5.2's parser (RapidJSON, default flags) reads it, so
// that a file cut short or not JSON is named at its line instead of "No suitable reader found".
#pragma once

#include <cstdint>
#include <istream>
#include <string>

namespace rt {

/// Walks the JSON in the next `bytes` bytes of `in`: one object, strict JSON, bytes above 127
/// taken as they are (RapidJSON does not check UTF-8), a 0 byte after the object ending the text
/// (as it ends RapidJSON's), arrays and objects nested at most 1000 deep (RapidJSON's recursion
/// overflowed the stack at 300,000). Nothing is kept. Throws InputError "name:line: expected ...,
/// found ..." at the first fault, the end included; for a .glb's JSON chunk (`chunk`), "name: line
/// N of the JSON chunk: ...".
void check_gltf_json(std::istream& in, std::uintmax_t bytes, const std::string& name, bool chunk);

}  // namespace rt
