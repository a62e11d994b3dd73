// merge PART... [--output FILE]...: joins the part files of `rt SCENE --tile I/N` into the .gro
// (and images) a single run of rt writes, pixel for pixel (docs/distributed.md). Reads the
// command line with CLI11, calls the image library, maps errors to exit codes.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rt/app/run.h"
#include "rt/core/error.h"
#include "rt/image/image_writer.h"
#include "rt/image/part_merge.h"

#include "command_line/command_line.h"

namespace {

// Exit codes shared with rt: 0 ok, 1 bad input file, 2 usage, 3 I/O, 4 internal.
constexpr int kOk = rt::cli::kOkExit;

struct MergeArgs {
    std::vector<std::string> parts;
    std::vector<std::string> outputs;
    bool no_gro = false;
};

void add_options(CLI::App& app, MergeArgs& m) {
    app.add_option("PART", m.parts, "the part files (rt SCENE --tile I/N writes them), any order")
        ->required()
        ->type_name("");
    app.add_option("-o,--output", m.outputs,
                   "also write the picture to FILE (.png, .ppm, .gro or .exr); may be\n"
                   "repeated")
        ->type_name("FILE");
    app.add_flag("-n,--no-gro", m.no_gro,
                 "do not write the scene's .gro (as rt -n), only the --output files");
}

// The .gro a single run of rt would have written: the scene's name, or the model's.
std::filesystem::path default_gro(const rt::Film& film) {
    const std::string& scene = film.provenance.scene;
    const std::string model_prefix = "--model ";
    if (scene.rfind(model_prefix, 0) == 0) {
        return rt::model_gro_path(scene.substr(model_prefix.size()));
    }
    return rt::default_gro_path(scene);
}

int run(const MergeArgs& m) {
    for (const std::string& output : m.outputs) {
        rt::image_format_for(output);  // a bad name fails before any reading
    }
    std::vector<std::filesystem::path> parts(m.parts.begin(), m.parts.end());
    const rt::Film film = rt::merge_parts(parts);
    std::vector<std::filesystem::path> outputs;
    if (!m.no_gro) {
        outputs.push_back(default_gro(film));
    }
    outputs.insert(outputs.end(), m.outputs.begin(), m.outputs.end());
    if (outputs.empty()) {
        throw rt::UsageError("-n leaves nothing to write: give --output FILE");
    }
    for (const std::filesystem::path& output : outputs) {
        rt::write_image(film, output);  // atomic: an existing file is replaced only when whole
    }
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    return rt::cli::exit_code_of("merge", [&] {
        CLI::App app(
            "Joins the part files of rt SCENE --tile I/N (one per part, I from 1 to N) into\n"
            "the .gro a single run of rt writes, pixel for pixel, and into the --output\n"
            "pictures. Refuses parts of different renders (scene, switches, seed, program),\n"
            "the same part twice, and names the missing parts.\n"
            "Exit codes: 0 ok, 1 bad part file, 2 usage (missing parts), 3 I/O, 4 internal.",
            "merge");
        rt::cli::configure(app);
        MergeArgs args;
        add_options(app, args);
        if (const std::optional<int> stop =
                rt::cli::parse(app, argc, argv, rt::cli::BareCommand::PrintsHelp)) {
            return *stop;
        }
        return run(args);
    });
}
