#include "rt/scene/read/grid_file_reader.h"

#include <algorithm>

#include "rt/core/text.h"
#include "rt/scene/read/counted_lines.h"
#include "rt/scene/read/line_fields.h"
#include "rt/scene/read/record_lines.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::string point_name(std::int64_t row, std::int64_t column) {
    return fmt::format("point (row {}, column {})", row, column);
}

}  // namespace

void expect_grid_size(const SourceText& source, const DollarLine& record, std::int64_t rows,
                      std::int64_t columns, const SourceLocation& named_at) {
    LineFields fields(source, record);
    const std::string what = fmt::format("'{} {}', the rows and columns of cells that {} gives",
                                         rows, columns, named_at.to_string());
    const auto found = [&] {
        std::string words;
        for (const Token& t : record.tokens) {
            if (!words.empty()) {
                words += ' ';
            }
            words += t.text;
        }
        return cat({"'", words, "'"});
    };
    if (record.tokens.size() != 2) {
        throw expected_found(source.at(record.line), what, found());
    }
    const std::int64_t file_rows = fields.integer("the rows of cells");
    const std::int64_t file_columns = fields.integer("the columns of cells");
    if (file_rows != rows || file_columns != columns) {
        throw expected_found(source.at(record.line), what, found());
    }
}

PolygonGrid read_grid_file(const SourceText& source, std::int64_t rows, std::int64_t columns,
                           const SourceLocation& named_at, Diagnostics& diagnostics) {
    RecordReader records(source);
    DollarLine record;
    if (!records.next(record)) {
        throw expected_found(records.end_location(), "the grid's rows and columns of cells",
                             "end of file");
    }
    expect_grid_size(source, record, rows, columns, named_at);
    PolygonGrid grid;
    grid.rows = rows;
    grid.columns = columns;
    const std::int64_t count = (rows + 1) * (columns + 1);
    const auto reserve = static_cast<std::size_t>(std::min(count, records.max_records_left()));
    grid.points.reserve(reserve);
    grid.lines.reserve(reserve);
    for (std::int64_t row = 0; row <= rows; ++row) {
        for (std::int64_t column = 0; column <= columns; ++column) {
            const std::string name = point_name(row, column);
            if (!records.next(record)) {
                throw expected_found(
                    records.end_location(),
                    fmt::format("{} of the {} x {} grid points", name, rows + 1, columns + 1),
                    "end of file");
            }
            LineFields fields(source, record);
            Vec3 p;
            p.x = fields.number("the x of " + name);
            p.y = fields.number("the y of " + name);
            p.z = fields.number("the z of " + name);
            expect_record_end(source, record, 3, name);
            grid.points.push_back(p);
            grid.lines.push_back(record.line);
            if (diagnostics.tracing()) {
                diagnostics.trace(fmt::format("{}: {} = {}", source.at(record.line).to_string(),
                                              name, show_point(p.x, p.y, p.z)));
            }
        }
    }
    LinesLeftOver left;
    while (records.next(record)) {
        left.add(record.line);
    }
    left.warn(source, "grid's points", "", diagnostics);
    return grid;
}

}  // namespace rt
