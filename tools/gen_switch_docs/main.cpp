// gen_switch_docs [PATH]: writes docs/switches.md, rendered from the switch table, to PATH (or to
// stdout). Run as `build/bin/gen_switch_docs docs/switches.md` after changing the table.
#include <exception>
#include <iostream>
#include <optional>
#include <ostream>
#include <string>

#include "rt/app/help.h"
#include "rt/core/atomic_file.h"

#include "command_line/command_line.h"

int main(int argc, char** argv) {
    try {
        CLI::App app(
            "Writes docs/switches.md, rendered from rt's switch table, to PATH (or to\n"
            "standard output).",
            "gen_switch_docs");
        rt::cli::configure(app);
        std::string path;
        app.add_option("PATH", path, "the file to write, e.g. docs/switches.md")->type_name("");
        if (const std::optional<int> stop =
                rt::cli::parse(app, argc, argv, rt::cli::BareCommand::Runs)) {
            return *stop;
        }
        const std::string text = rt::switches_markdown();
        if (path.empty()) {
            std::cout << text;
            return 0;
        }
        rt::write_file_atomically(path, [&text](std::ostream& out) { out << text; });
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "gen_switch_docs: " << e.what() << '\n';
        return 3;
    }
}
