// show NAME [--output FILE]... [--info] [-m F] [-c]: looks at a .gro picture written by rt
// (manual 1.2). Parses the command line, calls the image library, maps errors to exit codes.
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"
#include "rt/image/film_summary.h"
#include "rt/image/gro_format.h"
#include "rt/image/image_writer.h"

#include <fmt/format.h>

namespace {

// Exit codes shared with rt: 0 ok, 1 bad input file, 2 usage, 3 I/O, 4 internal.
constexpr int kOk = 0;
constexpr int kBadInput = 1;
constexpr int kUsage = 2;
constexpr int kIo = 3;
constexpr int kInternal = 4;

constexpr const char* kUsageText =
    "usage: show NAME [--output FILE]... [--info] [-m F] [-c]\n"
    "  NAME           the .gro picture, with or without the .gro suffix\n"
    "  --output FILE  write the picture to FILE (.png, .ppm or .gro); may be repeated\n"
    "  --info         print the picture's size, window, rows finished, display mapping,\n"
    "                 scene, switches, program and creation time\n"
    "  -m F, -mF      multiply display values by F (overrides the value stored in the file)\n"
    "  -c             no intensity clipping: overbright values wrap (can give very strange\n"
    "                 colors)\n"
    "  --help         print this text\n";

struct ShowArgs {
    std::string name;
    std::vector<std::string> outputs;
    bool info = false;
    bool help = false;
    std::optional<double> multiplier;
    bool no_clip = false;
};

double multiplier_argument(const std::string& text) {
    const std::optional<double> m = rt::parse_double(text);
    if (!m || *m < 0.0) {
        throw rt::UsageError("-m: expected a non-negative number, found " + rt::quote_token(text));
    }
    return *m;
}

ShowArgs parse_args(const std::vector<std::string>& args) {
    ShowArgs s;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto next = [&]() -> const std::string& {
            if (i + 1 >= args.size()) {
                throw rt::UsageError(fmt::format("expected an argument after {}, found none", a));
            }
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            s.help = true;
        } else if (a == "--info") {
            s.info = true;
        } else if (a == "--output" || a == "-o") {
            s.outputs.push_back(next());
        } else if (a.rfind("--output=", 0) == 0) {
            s.outputs.push_back(a.substr(9));
        } else if (a == "-m") {
            s.multiplier = multiplier_argument(next());
        } else if (a.rfind("-m", 0) == 0) {
            s.multiplier = multiplier_argument(a.substr(2));
        } else if (a == "-c") {
            s.no_clip = true;
        } else if (!a.empty() && a[0] == '-') {
            throw rt::UsageError("unknown option " + rt::quote_token(a));
        } else if (s.name.empty()) {
            s.name = a;
        } else {
            throw rt::UsageError("expected one picture name, found " + rt::quote_token(s.name) +
                                 " and " + rt::quote_token(a));
        }
    }
    if (!s.help && s.name.empty()) {
        throw rt::UsageError("expected a picture name");
    }
    return s;
}

// "show name" names name.gro; a name already ending in .gro, or an existing file, is taken as is.
std::filesystem::path gro_path(const std::string& name) {
    std::filesystem::path given(name);
    if (given.extension() == ".gro" || std::filesystem::is_regular_file(given)) {
        return given;
    }
    return std::filesystem::path(name + ".gro");
}

int run(const std::vector<std::string>& args) {
    if (args.empty()) {
        std::cout << kUsageText;
        return kOk;
    }
    const ShowArgs s = parse_args(args);
    if (s.help) {
        std::cout << kUsageText;
        return kOk;
    }
    for (const std::string& output : s.outputs) {
        rt::image_format_for(output);  // a bad name fails before any reading
    }
    if (s.outputs.empty() && !s.info) {
        throw rt::NotImplementedError(
            "displaying in a window is not implemented yet; use --output NAME.png or --info");
    }
    rt::Film film = rt::read_gro(gro_path(s.name));
    film.mapping.multiplier = s.multiplier.value_or(film.mapping.multiplier);
    film.mapping.clip = film.mapping.clip && !s.no_clip;
    if (s.info) {
        std::cout << rt::film_summary(film);
    }
    for (const std::string& output : s.outputs) {
        rt::write_image(film, output);
    }
    return kOk;
}

void print_error(const std::string& message) {
    std::cerr << "show: " << message << '\n';
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const rt::InputError& e) {
        print_error(e.what());
        return kBadInput;
    } catch (const rt::UsageError& e) {
        print_error(e.what());
        print_error("run 'show --help' for the options");
        return kUsage;
    } catch (const rt::NotImplementedError& e) {
        print_error(e.what());
        return kUsage;
    } catch (const rt::IoError& e) {
        print_error(e.what());
        return kIo;
    } catch (const std::exception& e) {
        print_error(std::string("internal error: ") + e.what());
        return kInternal;
    }
}
