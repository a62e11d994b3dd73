// The whole-scene target's input: a small scene folder in one text (fuzz/README.md). Parts start
// at marker lines "=== NAME [switches]"; the first part is the .scn, whatever its name, and the
// words after its name are the reader switches (-M -V -Df ...); the other parts are the files it
// names. An input without a marker line is a .scn alone.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rt::fuzz {

struct FolderFile {
    std::string name;  ///< relative, with '/' between folders; never absolute, never ".."
    std::string bytes;
};

struct SceneFolder {
    std::string scn;
    std::string switches;  ///< the words after the first marker's name
    std::vector<FolderFile> files;
};

inline constexpr std::string_view kPartMarker = "=== ";

/// Splits the input. A part whose name is unsafe (absolute, "..", odd characters) is dropped.
SceneFolder split_scene_folder(std::string_view input);

}  // namespace rt::fuzz
