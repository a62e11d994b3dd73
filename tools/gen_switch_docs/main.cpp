// gen_switch_docs [PATH]: writes docs/switches.md, rendered from the switch table, to PATH (or to
// stdout). Run as `build/bin/gen_switch_docs docs/switches.md` after changing the table.
#include <exception>
#include <iostream>
#include <ostream>
#include <string>

#include "rt/app/help.h"
#include "rt/core/atomic_file.h"

int main(int argc, char** argv) {
    const std::string text = rt::switches_markdown();
    if (argc < 2) {
        std::cout << text;
        return 0;
    }
    try {
        rt::write_file_atomically(argv[1], [&text](std::ostream& out) { out << text; });
    } catch (const std::exception& e) {
        std::cerr << "gen_switch_docs: " << e.what() << '\n';
        return 3;
    }
    return 0;
}
