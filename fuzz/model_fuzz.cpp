// Optical surface filetype 3: a model file through Assimp. The input's first word picks the
// format, as a file's extension would: "ply" a PLY file, "OFF" an OFF file, "solid" an ASCII STL
// file, "{" a glTF file, "glTF" a binary glTF file, anything else an OBJ file. Not every model
// message names a line (binary files have none).
#include "rt/core/diagnostics.h"
#include "rt/scene/read/model_reader.h"

#include "fuzz_input.h"

namespace {

std::string_view extension_for(std::string_view text) {
    if (text.starts_with("ply")) {
        return ".ply";
    }
    if (text.starts_with("OFF")) {
        return ".off";
    }
    if (text.starts_with("solid")) {
        return ".stl";
    }
    if (text.starts_with("{")) {
        return ".gltf";
    }
    if (text.starts_with("glTF")) {
        return ".glb";
    }
    return ".obj";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rt;
    const std::string_view text = fuzz::as_text(data, size);
    const std::string name = "model" + std::string(extension_for(text));
    const std::filesystem::path path = fuzz::write_scratch_file(name, text);
    fuzz::expect_value_or_input_error(
        [&] {
            Diagnostics diagnostics;
            return read_model_file(path, name, SourceLocation{"fuzz.scn", 1, 0}, diagnostics);
        },
        fuzz::Where::File);
    return 0;
}
