#include "nested_glass.h"

#include <sstream>
#include <stdexcept>

namespace rt::test {

namespace {

void replace_line(std::string& text, const std::string& line, const std::string& by) {
    const std::size_t at = text.find(line);
    if (at == std::string::npos) {
        throw std::runtime_error("nested-glass.scn: no line '" + line + "'");
    }
    text.replace(at, line.size(), by);
}

}  // namespace

void write_nested_glass(const TempDir& dir, const std::string& name, int maxdepth,
                        const std::string& window) {
    const std::filesystem::path data = source_dir() / "tests/data/scene/nested-glass";
    for (const char* file : {"Attributes", "cube", "square"}) {
        dir.write(file, read_text(data / file));
    }
    std::string scene = read_text(data / "nested-glass.scn");
    replace_line(scene, "$ 0 2 0 0 3 .5 16 1", "$ 0 2 0 0 3 .5 " + std::to_string(maxdepth) + " 1");
    replace_line(scene, "$ 0 0 31 23", "$ " + window);
    dir.write(name + ".scn", scene);
}

std::uint64_t rays_traced(const std::string& profile) {
    for (const std::string& line : lines_of(profile)) {
        std::istringstream words(line);
        std::string kind;
        std::uint64_t rays = 0;
        if (words >> kind >> rays && kind == "all") {
            return rays;
        }
    }
    throw std::runtime_error("no 'all' row in the profile:\n" + profile);
}

}  // namespace rt::test
