#include "scene_folder.h"

#include <algorithm>

namespace rt::fuzz {

namespace {

bool safe_name(std::string_view name) {
    if (name.empty() || name.size() > 64 || name.front() == '/' || name.back() == '/') {
        return false;
    }
    const bool plain = std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '.' || c == '_' || c == '-' || c == '/';
    });
    return plain && name.find("..") == std::string_view::npos &&
           name.find("//") == std::string_view::npos;
}

// The marker line's name and the words after it.
void split_marker(std::string_view line, std::string& name, std::string& rest) {
    line.remove_prefix(kPartMarker.size());
    const std::size_t space = line.find(' ');
    name = std::string(line.substr(0, space));
    rest = space == std::string_view::npos ? "" : std::string(line.substr(space + 1));
}

}  // namespace

SceneFolder split_scene_folder(std::string_view input) {
    SceneFolder folder;
    std::string* part = &folder.scn;  // text before the first marker belongs to the .scn
    bool first_marker = true;
    std::size_t pos = 0;
    while (pos < input.size()) {
        const std::size_t end = std::min(input.find('\n', pos), input.size());
        const std::string_view line = input.substr(pos, end - pos);
        const std::size_t next = end < input.size() ? end + 1 : end;
        if (line.starts_with(kPartMarker)) {
            std::string name;
            std::string rest;
            split_marker(line, name, rest);
            if (first_marker) {
                first_marker = false;
                folder.switches = rest;
                folder.scn.clear();
                part = &folder.scn;
            } else if (safe_name(name) && name != "fuzz.scn") {
                folder.files.push_back({name, {}});
                part = &folder.files.back().bytes;
            } else {
                part = nullptr;
            }
        } else if (part != nullptr) {
            part->append(input.substr(pos, next - pos));
        }
        pos = next;
    }
    return folder;
}

}  // namespace rt::fuzz
