// The JSON of a glTF file, parsed by RapidJSON, the parser Assimp 5.2 reads it with (default flags,
// in place), so that a file cut short or not JSON is named at its line instead of "No suitable
// reader found".
#pragma once

#include <cstdint>
#include <istream>
#include <string>

namespace rt {

/// Parses the JSON in the next `bytes` bytes of `in` as Assimp does: one object, strict JSON, bytes
/// above 127 taken as they are (RapidJSON does not check UTF-8), a 0 byte after the object ending
/// the text (as it ends Assimp's copy), and, beyond Assimp, arrays and objects nested at most 1000
/// deep (Assimp's recursive parse overflowed the stack at 300,000). Nothing is kept. Throws
/// InputError "name:line: expected ..., found ..." at the first fault, the end included; for a
/// .glb's JSON chunk (`chunk`), "name: line N of the JSON chunk: ...".
void check_gltf_json(std::istream& in, std::uintmax_t bytes, const std::string& name, bool chunk);

}  // namespace rt
