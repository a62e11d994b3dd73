// show NAME [--output FILE]... [--info] [-m F] [-c]: looks at a .gro (or .exr) picture written by
// rt (manual 1.2), in a window or converted. Reads the command line with CLI11, calls the image
// library, maps errors to exit codes.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "rt/core/error.h"
#include "rt/image/film_summary.h"
#include "rt/image/gro_format.h"
#include "rt/image/image_writer.h"

#include "command_line/command_line.h"
#include "show/show_window.h"

namespace {

// Exit codes shared with rt: 0 ok, 1 bad input file, 2 usage, 3 I/O, 4 internal.
constexpr int kOk = rt::cli::kOkExit;

struct ShowArgs {
    std::string name;
    std::vector<std::string> outputs;
    bool info = false;
    std::optional<double> multiplier;
    bool no_clip = false;
};

// The manual's "show name", with the conversions rt adds. A repeated -m or -c: the last wins.
void add_options(CLI::App& app, ShowArgs& s) {
    app.add_option("NAME", s.name,
                   "the .gro picture, with or without the .gro suffix, or an .exr picture")
        ->required()
        ->type_name("");
    app.add_option("-o,--output", s.outputs,
                   "write the picture to FILE (.png, .ppm, .gro or .exr); may be\n"
                   "repeated")
        ->type_name("FILE");
    app.add_flag("--info", s.info,
                 "print the picture's size, window, rows finished, display mapping,\n"
                 "scene, switches, program and creation time");
    app.add_option("-m", s.multiplier,
                   "multiply display values by F, also written -mF (overrides the\n"
                   "value stored in the file)")
        ->type_name("F")
        ->check(rt::cli::number_at_least(0.0));
    app.add_flag("-c", s.no_clip,
                 "no intensity clipping: overbright values wrap (can give very\n"
                 "strange colors)");
}

// "show name" names name.gro; a name already ending in .gro or .exr, or an existing file, is taken
// as is.
std::filesystem::path picture_path(const std::string& name) {
    std::filesystem::path given(name);
    std::error_code error;  // a name the system cannot look up: the reader says why
    if (given.extension() == ".gro" || given.extension() == ".exr" ||
        std::filesystem::is_regular_file(given, error)) {
        return given;
    }
    return std::filesystem::path(name + ".gro");
}

int run(const ShowArgs& s) {
    for (const std::string& output : s.outputs) {
        rt::image_format_for(output);  // a bad name fails before any reading
    }
    const bool in_window = s.outputs.empty() && !s.info;  // the manual's "show name"
    const std::filesystem::path path = picture_path(s.name);
    if (s.info && s.outputs.empty() && path.extension() == ".gro") {
        // The header says it all: the pixels, gigabytes for a large view, are never read.
        rt::GroHeader header = rt::read_gro_header_only(path);
        header.mapping.multiplier = s.multiplier.value_or(header.mapping.multiplier);
        header.mapping.clip = header.mapping.clip && !s.no_clip;
        std::cout << rt::header_summary(header);
        return kOk;
    }
    rt::Film film = rt::show::read_shown_picture(path);
    film.mapping.multiplier = s.multiplier.value_or(film.mapping.multiplier);
    film.mapping.clip = film.mapping.clip && !s.no_clip;
    if (in_window) {
        return rt::show::show_in_window(film, path.filename().string());
    }
    if (s.info) {
        std::cout << rt::film_summary(film);
    }
    for (const std::string& output : s.outputs) {
        rt::write_image(film, output);
    }
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    return rt::cli::exit_code_of(
        "show",
        [&] {
            CLI::App app(
                "Looks at a .gro picture written by rt (manual 1.2), or an .exr, .png or .ppm:\n"
                "shows it in a window (keys + and - change the exposure, 0 restores it, Esc or\n"
                "Enter closes it), prints what it holds, or converts it to PNG, PPM, .gro or\n"
                ".exr. Without a display, \"show NAME\" prints what --info prints.\n"
                "Exit codes: 0 ok, 1 bad picture (or the window's display went away),\n"
                "2 usage, 3 I/O, 4 internal.",
                "show");
            rt::cli::configure(app);
            ShowArgs args;
            add_options(app, args);
            if (const std::optional<int> stop =
                    rt::cli::parse(app, argc, argv, rt::cli::BareCommand::PrintsHelp)) {
                return *stop;
            }
            return run(args);
        },
        "run 'show --help' for the options");
}
