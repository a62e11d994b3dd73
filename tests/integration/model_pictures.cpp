#include "model_pictures.h"

#include <sstream>

#include "support/temp_dir.h"

namespace rt::test {

std::string gro_pixels(const std::filesystem::path& gro) {
    const std::string bytes = read_text(gro);
    const std::size_t end = bytes.find("\nend\n");
    return end == std::string::npos ? std::string() : bytes.substr(end + 5);
}

std::string bunny_as_obj() {
    std::istringstream ply(read_text(source_dir() / "scenes/models/bunny.ply"));
    std::string line;
    long vertices = 0;
    long faces = 0;
    while (std::getline(ply, line) && line != "end_header") {
        std::istringstream words(line);
        std::string key;
        std::string element;
        long count = 0;
        if (words >> key >> element >> count && key == "element") {
            (element == "vertex" ? vertices : faces) = count;
        }
    }
    std::string obj;
    for (long i = 0; i < vertices && std::getline(ply, line); ++i) {
        obj.append("v ").append(line).append("\n");
    }
    for (long i = 0; i < faces && std::getline(ply, line); ++i) {
        std::istringstream words(line);
        long n = 0;
        words >> n;
        obj += "f";
        for (long k = 0, v = 0; k < n && words >> v; ++k) {
            obj.append(" ").append(std::to_string(v + 1));
        }
        obj += "\n";
    }
    return obj;
}

}  // namespace rt::test
