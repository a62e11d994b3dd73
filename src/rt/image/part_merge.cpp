#include "rt/image/part_merge.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "rt/core/error.h"
#include "rt/image/gro_format.h"
#include "rt/image/picture_parts.h"

#include <fmt/format.h>

namespace rt {

namespace {

struct PartFile {
    std::filesystem::path path;
    GroHeader header;
    PicturePart part;
};

// The header lines that differ between the parts of one render; every other line must agree.
bool varies_between_parts(std::string_view key) {
    return key == "window" || key == "first_finished_row" || key == "created" || key == "part";
}

std::map<std::string, std::string> identity_fields(const GroHeader& header) {
    std::map<std::string, std::string> fields;
    for (const auto& [key, value] : header.fields) {
        if (!varies_between_parts(key)) {
            fields.emplace(key, value);
        }
    }
    return fields;
}

InputError part_error(const std::filesystem::path& path, const std::string& message) {
    return InputError({path.string(), 0, 0}, message);
}

PartFile read_part_header(const std::filesystem::path& path) {
    PartFile file{path, read_gro_header_only(path), {}};
    const std::optional<PicturePart> part = parse_part_line(file.header.part.part);
    if (!part) {
        throw part_error(path, file.header.part.part.empty()
                                   ? "not a part file (no 'part' line: rt --tile I/N writes them)"
                                   : "expected a 'part I N' line with 1 <= I <= N, found 'part " +
                                         file.header.part.part + "'");
    }
    file.part = *part;
    if (file.header.first_finished_row > file.header.window.top) {
        throw part_error(path, fmt::format("part {} is unfinished (rows above {} were not "
                                           "rendered): render it again",
                                           part->index, file.header.first_finished_row));
    }
    return file;
}

// Every part must come from the same render as the first.
void check_same_render(const PartFile& first, const PartFile& other) {
    if (other.part.count != first.part.count) {
        throw part_error(
            other.path,
            fmt::format("part {} of {}, but {} is part {} of {}", other.part.index,
                        other.part.count, first.path.string(), first.part.index, first.part.count));
    }
    const auto a = identity_fields(first.header);
    const auto b = identity_fields(other.header);
    if (a == b) {
        return;
    }
    for (const auto& [key, value] : first.header.fields) {  // in the file's order
        if (varies_between_parts(key)) {
            continue;
        }
        const auto found = b.find(key);
        const std::string theirs = found == b.end() ? "none" : "'" + found->second + "'";
        if (found == b.end() || found->second != value) {
            throw part_error(
                other.path, fmt::format("a part of another render: its {} is {}, {}'s is '{}'", key,
                                        theirs, first.path.string(), value));
        }
    }
    for (const auto& [key, value] : b) {
        if (a.find(key) == a.end()) {
            throw part_error(other.path,
                             fmt::format("a part of another render: its {} is '{}', {} has none",
                                         key, value, first.path.string()));
        }
    }
}

std::string list_numbers(const std::vector<int>& numbers) {
    std::string text;
    for (std::size_t i = 0; i < numbers.size(); ++i) {
        text += i == 0 ? "" : i + 1 == numbers.size() ? " and " : ", ";
        text += std::to_string(numbers[i]);
    }
    return text;
}

// Each part once, and none missing; returns the parts by number.
std::vector<const PartFile*> parts_in_order(const std::vector<PartFile>& files) {
    const int count = files.front().part.count;
    std::vector<const PartFile*> by_index(static_cast<std::size_t>(count), nullptr);
    for (const PartFile& file : files) {
        const PartFile*& slot = by_index[static_cast<std::size_t>(file.part.index - 1)];
        if (slot != nullptr) {
            throw part_error(file.path, fmt::format("part {} is given twice (also {})",
                                                    file.part.index, slot->path.string()));
        }
        slot = &file;
    }
    std::vector<int> missing;
    for (int i = 0; i < count; ++i) {
        if (by_index[static_cast<std::size_t>(i)] == nullptr) {
            missing.push_back(i + 1);
        }
    }
    if (!missing.empty()) {
        throw UsageError(fmt::format("missing part{} {} of {}: give every part file",
                                     missing.size() == 1 ? "" : "s", list_numbers(missing), count));
    }
    return by_index;
}

// The whole window: the bands' union, each band where part_window puts it.
PixelRect whole_window(const std::vector<const PartFile*>& parts) {
    PixelRect whole = parts.front()->header.window;
    for (const PartFile* p : parts) {
        whole.top = std::min(whole.top, p->header.window.top);
        whole.bottom = std::max(whole.bottom, p->header.window.bottom);
    }
    for (const PartFile* p : parts) {
        const PixelRect& w = p->header.window;
        const PixelRect expected = whole.height() >= p->part.count ? part_window(whole, p->part)
                                                                   : PixelRect{-1, -1, -1, -1};
        if (!(w == expected)) {
            throw part_error(
                p->path, fmt::format("its window {} {} {} {} is not part {} of {} of the "
                                     "window {} {} {} {} (left top right bottom)",
                                     w.left, w.top, w.right, w.bottom, p->part.index, p->part.count,
                                     whole.left, whole.top, whole.right, whole.bottom));
        }
    }
    return whole;
}

}  // namespace

Film merge_parts(const std::vector<std::filesystem::path>& paths) {
    if (paths.empty()) {
        throw UsageError("no part files given");
    }
    std::vector<PartFile> files;
    files.reserve(paths.size());
    for (const std::filesystem::path& path : paths) {
        files.push_back(read_part_header(path));
        check_same_render(files.front(), files.back());
    }
    const std::vector<const PartFile*> parts = parts_in_order(files);
    const PixelRect whole = whole_window(parts);
    const GroHeader& first = parts.front()->header;
    Film merged(first.view_width, first.view_height, whole);
    for (const PartFile* p : parts) {
        const Film film = read_gro(p->path);
        const PixelRect& w = film.window();
        const auto offset = static_cast<std::size_t>(w.top - whole.top) *
                            static_cast<std::size_t>(whole.width()) * 3;
        std::copy(film.data().begin(), film.data().end(),
                  merged.data().begin() + static_cast<std::ptrdiff_t>(offset));
    }
    merged.set_first_finished_row(whole.top);
    merged.mapping = first.mapping;
    merged.provenance = first.provenance;
    return merged;
}

}  // namespace rt
