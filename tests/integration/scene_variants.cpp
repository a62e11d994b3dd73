#include "scene_variants.h"

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "support/temp_dir.h"

namespace rt::test {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kAttributesLine = "$ gallery-attributes";
// The gallery's surface files (filetype 0) and its sphere.
const std::vector<std::string> surface_files{"checker8", "square", "cube", "sphere"};
constexpr std::string_view kSphereFile = "sphere";
// Surfaces (their index numbers in gallery.scn) that "smooth" shades: the sphere, the red cube
// (whose averaged corner normals lean far off its faces, for -Ot and -E), and the glass pane in
// front of the yellow light (transparent, so that -Po has something to make opaque).
const std::set<std::string> smooth_surfaces{"14", "8", "11"};
constexpr std::string_view kGlassIndex = "6";  // the clear glass attribute

std::string join(const std::vector<std::string>& fields) {
    std::string line;
    for (const std::string& f : fields) {
        line += (line.empty() ? "" : " ") + f;
    }
    return line;
}

std::string text_of(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += line + "\n";
    }
    return text;
}

void write(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) {
        throw std::runtime_error("cannot write " + path.string());
    }
}

bool is_number(const std::string& word) {
    std::istringstream in(word);
    double value = 0.0;
    return static_cast<bool>(in >> value) && in.eof();
}

// The surface lines of a .scn ("$ index attribute filetype name scale tx ty tz rx ry rz") with
// the smooth-shade field put after the filetype.
std::string with_smooth_field(const std::string& scn, const std::set<std::string>& smooth) {
    std::vector<std::string> lines = lines_of(scn);
    for (std::string& line : lines) {
        std::vector<std::string> w = words(line);
        if (w.size() == 12 && w[0] == "$" && !is_number(w[4])) {
            w.insert(w.begin() + 4, smooth.contains(w[1]) ? "1" : "0");
            line = join(w);
        }
    }
    return text_of(lines);
}

std::string replace_line(const std::string& text, std::string_view line,
                         const std::string& replacement) {
    const std::size_t at = text.find(std::string(line) + "\n");
    if (at == std::string::npos) {
        throw std::runtime_error("no line '" + std::string(line) + "'");
    }
    return text.substr(0, at) + replacement + text.substr(at + line.size() + 1);
}

// The `$` lines of an Attributes file: its count and its attributes, as -Df wants them inline.
std::string attribute_block(const std::string& attributes) {
    std::string block;
    for (const std::string& line : lines_of(attributes)) {
        if (!words(line).empty() && words(line)[0] == "$") {
            block += line + "\n";
        }
    }
    return block;
}

std::string without_power(const std::vector<std::string>& f) {
    std::vector<std::string> out = f;
    out.erase(out.begin() + 4, out.begin() + 6);  // "$ r g b pow tpow e ...": pow and tpow
    return join(out);
}

std::string power_two(const std::vector<std::string>& f) {
    std::vector<std::string> out = f;
    out[4] = "2.0";
    out[5] = "2.0";
    return join(out);
}

std::string index_thrice(const std::vector<std::string>& f) {
    std::vector<std::string> out = f;
    const std::string ref = out[11];  // "$ r g b pow tpow e a d s t ref ..."
    out.insert(out.begin() + 12, {ref, ref});
    return join(out);
}

std::string glass_spread(const std::vector<std::string>& f) {
    std::vector<std::string> out = f;
    out.insert(out.begin() + 12, {out[11], out[11]});
    if (out[18] == kGlassIndex) {  // the index number, after the three indices and four cones
        out[11] = "1.3";
        out[12] = "1.5";
        out[13] = "1.7";
    }
    return join(out);
}

}  // namespace

std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string w; in >> w;) {
        out.push_back(w);
    }
    return out;
}

std::string edit_attributes(const std::string& text,
                            std::string (*edit)(const std::vector<std::string>& fields)) {
    std::vector<std::string> lines = lines_of(text);
    bool counted = false;
    for (std::string& line : lines) {
        const std::vector<std::string> w = words(line);
        if (w.empty() || w[0] != "$") {
            continue;
        }
        if (!counted) {
            counted = true;  // the count
            continue;
        }
        line = edit(w);
    }
    return text_of(lines);
}

std::string with_marks(const std::string& surface_file, int mark, int shape) {
    std::istringstream in(surface_file);
    std::ostringstream out;
    const auto copy_block = [&](int fields) {
        std::size_t count = 0;
        in >> count;
        out << count << "\n";
        for (std::size_t k = 0; k < count; ++k) {
            std::string word;
            for (int f = 0; f < fields; ++f) {
                in >> word;
                out << (f == 0 ? "" : " ") << word;
            }
            out << "\n";
        }
    };
    copy_block(4);  // vertices: index x y z
    copy_block(3);  // edges: index v1 v2
    std::size_t polygons = 0;
    in >> polygons;
    out << polygons << "\n";
    for (std::size_t k = 0; k < polygons; ++k) {
        std::string index;
        std::size_t edges = 0;
        in >> index >> edges;
        out << index << " " << edges;
        for (std::size_t f = 0; f < edges + 4; ++f) {  // edges, the outward normal, the offset
            std::string word;
            in >> word;
            out << " " << word;
        }
        out << " " << mark << " " << shape << "\n";
    }
    if (!in) {
        throw std::runtime_error("not a filetype-0 surface file");
    }
    return out.str();
}

fs::path write_gallery_variant(std::string_view variant, const fs::path& folder) {
    fs::create_directories(folder);
    fs::copy(source_dir() / "scenes", folder, fs::copy_options::recursive);
    fs::path scn = folder / "gallery.scn";
    const fs::path attributes = folder / "gallery-attributes";
    const std::string scn_text = read_text(scn);
    const std::string attributes_text = read_text(attributes);
    if (variant == "smooth" || variant == "flat-field") {
        write(scn, with_smooth_field(
                       scn_text, variant == "smooth" ? smooth_surfaces : std::set<std::string>{}));
    } else if (variant == "marked" || variant == "marked-plain") {
        write(scn, replace_line(scn_text, kAttributesLine,
                                std::string(kAttributesLine) + "\n$@gallery-shapes\n"));
        write(folder / "gallery-shapes", "shapes\n$ 1\n$ 0 0 0 1 0 0 0 the sphere, radius 1\n");
        for (const std::string& file : surface_files) {
            const bool sphere = file == kSphereFile && variant == "marked";
            write(folder / file, with_marks(read_text(folder / file), sphere ? 2 : 0, 0));
        }
    } else if (variant == "inline" || variant == "old-format") {
        const std::string attrs =
            variant == "inline" ? attributes_text : edit_attributes(attributes_text, without_power);
        write(scn, replace_line(scn_text, kAttributesLine, attribute_block(attrs)));
    } else if (variant == "no-power") {
        write(attributes, edit_attributes(attributes_text, without_power));
    } else if (variant == "power-two") {
        write(attributes, edit_attributes(attributes_text, power_two));
    } else if (variant == "rgb-equal") {
        write(attributes, edit_attributes(attributes_text, index_thrice));
    } else if (variant == "rgb-spread") {
        write(attributes, edit_attributes(attributes_text, glass_spread));
    } else if (variant != "original") {
        throw std::invalid_argument("no variant " + std::string(variant));
    }
    return scn;
}

}  // namespace rt::test
