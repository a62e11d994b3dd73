#include "rt/scene/read/texture_map_reader.h"

#include <algorithm>

#include "rt/core/text.h"
#include "rt/scene/read/counted_lines.h"
#include "rt/scene/read/grid_file_reader.h"
#include "rt/scene/read/line_fields.h"
#include "rt/scene/read/reader_limits.h"
#include "rt/scene/read/record_lines.h"

#include <fmt/format.h>

namespace rt {

namespace {

class TextureMapReader {
public:
    TextureMapReader(const SourceText& source, Diagnostics& diagnostics)
        : source_(source), records_(source), diagnostics_(diagnostics) {}

    TextureMap read(std::int64_t rows, std::int64_t columns, const SourceLocation& named_at);

private:
    void trace(const std::string& text) {
        if (diagnostics_.tracing()) {
            diagnostics_.trace(source_.at(record_.line).to_string() + ": " + text);
        }
    }
    bool next() { return records_.next(record_); }
    /// The header's records, up to the first element (a record that starts with a number).
    void read_header();
    void read_centre();
    void read_picture(std::optional<MapPicture>& picture);
    TextureElement read_element(const std::string& name);
    double unit_factor(LineFields& fields, const std::string& what);

    const SourceText& source_;
    RecordReader records_;
    DollarLine record_;
    Diagnostics& diagnostics_;
    TextureMap map_;
};

TextureMap TextureMapReader::read(std::int64_t rows, std::int64_t columns,
                                  const SourceLocation& named_at) {
    if (!next()) {
        throw expected_found(records_.end_location(), "the texture map's rows and columns of cells",
                             "end of file");
    }
    expect_grid_size(source_, record_, rows, columns, named_at);
    read_header();
    const std::int64_t count = rows * columns;
    map_.elements.reserve(
        static_cast<std::size_t>(std::min(count, records_.max_records_left() + 1)));
    for (std::int64_t k = 0; k < count; ++k) {
        const std::string name =
            fmt::format("the element of cell (row {}, column {})", k / columns, k % columns);
        if (k > 0 && !next()) {
            throw expected_found(records_.end_location(),
                                 fmt::format("{} of the {} x {} cells", name, rows, columns),
                                 "end of file");
        }
        map_.elements.push_back(read_element(name));
    }
    LinesLeftOver left;
    while (next()) {
        left.add(record_.line);
    }
    left.warn(source_, "texture map's elements", "", diagnostics_);
    return std::move(map_);
}

void TextureMapReader::read_header() {
    while (true) {
        if (!next()) {
            const char* what = map_.centres.empty() ? "an optical centre line 'centre u v'"
                                                    : "the elements of the cells";
            throw expected_found(records_.end_location(), what, "end of file");
        }
        const std::string_view word = record_.tokens.front().text;
        if (parse_double(word)) {
            if (map_.centres.empty()) {
                throw expected_found(source_.at(record_.line),
                                     "an optical centre line 'centre u v' before the elements",
                                     quote_token(word));
            }
            return;  // the first element
        }
        if (word == "centre") {
            read_centre();
        } else if (word == "colour_map") {
            read_picture(map_.colour_map);
        } else if (word == "normal_map") {
            read_picture(map_.normal_map);
        } else {
            throw expected_found(source_.at(record_.line),
                                 "'centre', 'colour_map', 'normal_map' or the first element of "
                                 "the cells",
                                 quote_token(word));
        }
    }
}

void TextureMapReader::read_centre() {
    if (std::ssize(map_.centres) >= kMaxOpticalCentres) {
        throw InputError(
            source_.at(record_.line),
            fmt::format("more than the limit of {} optical centres", kMaxOpticalCentres));
    }
    const std::string name = fmt::format("optical centre {}", map_.centres.size());
    const auto number = [&](std::size_t k, const std::string& what) {
        if (k >= record_.tokens.size()) {
            throw expected_found(source_.at(record_.line), what, "end of line");
        }
        return number_from(source_, record_.tokens[k], what);
    };
    GridPoint p;  // after the word 'centre'
    p.u = number(1, "the u of " + name);
    p.v = number(2, "the v of " + name);
    expect_record_end(source_, record_, 3, name);
    map_.centres.push_back(p);
    trace(fmt::format("{} at u {} v {}", name, p.u, p.v));
}

void TextureMapReader::read_picture(std::optional<MapPicture>& picture) {
    const std::string kind(record_.tokens.front().text);
    if (picture) {
        throw InputError(source_.at(record_.line), fmt::format("a second {} line (the first is at "
                                                               "line {})",
                                                               kind, picture->line));
    }
    if (record_.tokens.size() < 2) {
        throw expected_found(source_.at(record_.line), "the file name of the " + kind,
                             "end of line");
    }
    expect_record_end(source_, record_, 2, "the file name of the " + kind);
    picture = MapPicture{std::string(record_.tokens[1].text), record_.line};
    trace(fmt::format("{} '{}'", kind, picture->name));
}

double TextureMapReader::unit_factor(LineFields& fields, const std::string& what) {
    const double value = fields.number(what);
    if (!(value >= 0.0 && value <= 1.0)) {
        throw expected_found(fields.location(), what + " (0 to 1)",
                             cat({"'", show_number(value), "'"}));
    }
    return value;
}

TextureElement TextureMapReader::read_element(const std::string& name) {
    LineFields fields(source_, record_);
    TextureElement e;
    e.line = record_.line;
    const std::int64_t centres = std::ssize(map_.centres);
    const std::int64_t centre = fields.integer("the optical centre of " + name);
    if (centre < 0 || centre >= centres) {
        throw expected_found(fields.location(),
                             fmt::format("the optical centre of {} (0 to {})", name, centres - 1),
                             cat({"'", std::to_string(centre), "'"}));
    }
    e.centre = static_cast<std::uint32_t>(centre);
    e.sphere = fields.number("the sphere curvature of " + name);
    e.cylinder = fields.number("the cylinder curvature of " + name);
    e.axis_degrees = fields.number("the cylinder axis of " + name);
    e.color.r = unit_factor(fields, "the red factor of " + name);
    e.color.g = unit_factor(fields, "the green factor of " + name);
    e.color.b = unit_factor(fields, "the blue factor of " + name);
    expect_record_end(source_, record_, 7, name);
    trace(fmt::format("{}: centre {} sphere {} cylinder {} axis {} colour {}", name, e.centre,
                      e.sphere, e.cylinder, e.axis_degrees,
                      show_point(e.color.r, e.color.g, e.color.b)));
    return e;
}

}  // namespace

TextureMap read_texture_map(const SourceText& source, std::int64_t rows, std::int64_t columns,
                            const SourceLocation& named_at, Diagnostics& diagnostics) {
    return TextureMapReader(source, diagnostics).read(rows, columns, named_at);
}

}  // namespace rt
