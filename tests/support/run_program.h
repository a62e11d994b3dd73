// Runs one of the built programs as a user would, capturing its exit status and output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rt::test {

struct ProgramResult {
    int exit_code = -1;
    std::string out;  ///< standard output
    std::string err;  ///< standard error
};

/// Runs bin_dir()/program with args in the folder cwd, standard input read from `input`.
ProgramResult run_program(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& cwd,
                          const std::filesystem::path& input = "/dev/null");

/// `word` in single quotes for the shell, its own single quotes escaped.
std::string shell_quote(const std::string& word);

/// Runs a shell command line (a pipeline if need be) in the folder `cwd`, standard input empty;
/// `out` holds its output and errors together.
ProgramResult run_shell(const std::string& command, const std::filesystem::path& cwd);

}  // namespace rt::test
