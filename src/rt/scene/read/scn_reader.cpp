#include "rt/scene/read/scn_reader.h"

#include <filesystem>
#include <system_error>

#include "rt/core/text.h"
#include "rt/scene/read/attributes_reader.h"
#include "rt/scene/read/item_stream.h"
#include "rt/scene/read/scn_entities.h"
#include "rt/scene/read/scn_view.h"

namespace rt {

namespace {

void trace(ItemStream& scn, Diagnostics& diagnostics, const std::string& text) {
    if (diagnostics.tracing()) {
        diagnostics.trace(scn.source().at(scn.line()).to_string() + ": " + text);
    }
}

// "$@name" and "$ @name" both give the token "@name"; "$ @ name" is accepted too.
std::optional<NamedFile> read_shape_line(ItemStream& scn, const ReaderDialect& dialect) {
    const Token* next = scn.peek();
    if (next == nullptr || next->text.front() != '@') {
        if (dialect.marks) {
            const std::string found = next ? quote_token(next->text) : "end of file";
            throw expected_found(next ? location_of(scn.source(), *next) : scn.end_location(),
                                 "the shape file line $@name (-M needs one)", found);
        }
        return std::nullopt;
    }
    const Token at = scn.take("the shape file line");
    const SourceLocation where = location_of(scn.source(), at);
    if (!dialect.marks) {
        throw InputError(where, "the scene names a shape file; use -M");
    }
    std::string name(at.text.substr(1));
    if (name.empty()) {
        if (!scn.next_on_same_line()) {
            throw expected_found(where, "a shape file name after '@'", "end of line");
        }
        name = std::string(scn.take("a shape file name").text);
    }
    scn.end_item();
    return NamedFile{name, where};
}

void read_attributes_item(ItemStream& scn, const ReaderDialect& dialect, ScnFile& scene,
                          Diagnostics& diagnostics) {
    if (dialect.attributes_inline) {
        scene.inline_attributes = read_inline_attributes(scn, dialect, diagnostics);
        return;
    }
    const Token name = scn.take("the name of the attributes file");
    // Attributes written in the .scn itself (manual 2.3) start with their count where the file's
    // name stands; without -Df that count was taken for a name, the attributes read as entities,
    // and "cannot open the attributes file '13'" came last. A number that names no file says so.
    std::error_code error;
    if (parse_double(name.text) &&
        !std::filesystem::exists(
            std::filesystem::path(scn.source().name).parent_path() / std::string(name.text),
            error)) {
        throw expected_found(location_of(scn.source(), name), "the name of the attributes file",
                             quote_token(name.text) +
                                 ", a number: attributes written in the .scn itself, after their "
                                 "count, are read with -Df");
    }
    scene.attributes_file = NamedFile{std::string(name.text), location_of(scn.source(), name)};
    scn.end_item();
    trace(scn, diagnostics, "attributes file '" + scene.attributes_file->name + "'");
}

}  // namespace

ScnFile read_scn(const SourceText& source, const ReaderDialect& dialect, Diagnostics& diagnostics) {
    ItemStream scn(source);
    ScnFile scene;
    scene.header = read_header(scn, diagnostics);
    scene.view = read_view(scn, scene.header, scene.eye_at, diagnostics);
    read_attributes_item(scn, dialect, scene, diagnostics);
    scene.shape_file = read_shape_line(scn, dialect);
    if (scene.shape_file) {
        trace(scn, diagnostics, "shape file '" + scene.shape_file->name + "'");
    }
    read_entities(scn, dialect, scene, diagnostics);
    read_after_entities(scn, dialect, scene, diagnostics);
    return scene;
}

}  // namespace rt
