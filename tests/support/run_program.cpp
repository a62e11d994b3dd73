#include "support/run_program.h"

#include <cstdlib>

#include "support/temp_dir.h"
#include <sys/wait.h>

namespace rt::test {

std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (char c : word) {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

ProgramResult run_program(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& cwd, const std::filesystem::path& input) {
    const TempDir capture;
    // Never on a display: these runs are headless whatever the test's environment names.
    std::string command = "cd " + shell_quote(cwd.string()) +
                          " && env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " +
                          shell_quote((bin_dir() / program).string());
    for (const std::string& a : args) {
        command += " " + shell_quote(a);
    }
    const std::filesystem::path out = capture.path() / "out";
    const std::filesystem::path err = capture.path() / "err";
    command += " <" + shell_quote(input.string()) + " >" + shell_quote(out.string()) + " 2>" +
               shell_quote(err.string());
    const int status = std::system(command.c_str());  // NOLINT(concurrency-mt-unsafe)
    ProgramResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text(out);
    result.err = read_text(err);
    return result;
}

ProgramResult run_shell(const std::string& command, const std::filesystem::path& cwd) {
    const TempDir capture;
    const std::filesystem::path out = capture.path() / "out";
    // In parentheses, so that the redirections apply to the whole of a pipeline.
    const std::string line = "cd " + shell_quote(cwd.string()) + " && (" + command +
                             ") </dev/null >" + shell_quote(out.string()) + " 2>&1";
    const int status = std::system(line.c_str());  // NOLINT(concurrency-mt-unsafe)
    ProgramResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text(out);
    return result;
}

}  // namespace rt::test
