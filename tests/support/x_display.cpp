#include "support/x_display.h"

#include <array>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "support/hand_readers.h"
#include "support/temp_dir.h"
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX names it so

namespace rt::test {

namespace {

#ifndef __has_feature
#define __has_feature(x) 0  // GCC 12 has no __has_feature; it says __SANITIZE_ADDRESS__ instead
#endif
#if defined(__SANITIZE_ADDRESS__) || __has_feature(address_sanitizer)
// Under AddressSanitizer (scripts/build-and-test-sanitized) the programs run several times
// slower; the limits stretch with them, so that a limit still means "hangs", not "is slow".
constexpr int kSlowdown = 5;
#else
constexpr int kSlowdown = 1;
#endif

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");  // NOLINT(concurrency-mt-unsafe)
    std::stringstream folders(path != nullptr ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        if (!folder.empty() && ::access((folder + "/" + program).c_str(), X_OK) == 0) {
            return true;
        }
    }
    return false;
}

// The environment for a child, with DISPLAY as asked and no other display named.
std::vector<std::string> child_environment(const std::optional<std::string>& display) {
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string entry(*e);
        if (entry.starts_with("DISPLAY=") || entry.starts_with("WAYLAND_DISPLAY=") ||
            entry.starts_with("SDL_VIDEODRIVER=")) {
            continue;
        }
        env.push_back(entry);
    }
    if (display) {
        env.push_back("DISPLAY=" + *display);
    }
    return env;
}

std::vector<char*> pointers(std::vector<std::string>& words) {
    std::vector<char*> p;
    for (std::string& w : words) {
        p.push_back(w.data());
    }
    p.push_back(nullptr);
    return p;
}

}  // namespace

std::string missing_display_tools() {
    for (const char* tool : {"Xvfb", "xwd", "convert"}) {
        if (!on_path(tool)) {
            return std::string(tool) +
                   " is not installed (scripts/install-deps installs xvfb, x11-apps, imagemagick)";
        }
    }
    return "";
}

XDisplay::XDisplay() {
    std::array<int, 2> pipe_ends{};
    if (::pipe(pipe_ends.data()) != 0) {
        ADD_FAILURE() << "pipe: " << std::strerror(errno);
        return;
    }
    std::vector<std::string> argv = {"Xvfb",      "-displayfd", std::to_string(pipe_ends[1]),
                                     "-screen",   "0",          "640x480x24",
                                     "-nolisten", "tcp"};
    std::vector<char*> args = pointers(argv);
    pid_ = ::fork();
    if (pid_ == 0) {
        ::close(pipe_ends[0]);
        const int quiet = ::open("/dev/null", O_WRONLY);
        ::dup2(quiet, STDOUT_FILENO);
        ::dup2(quiet, STDERR_FILENO);
        ::execvp("Xvfb", args.data());
        ::_exit(127);
    }
    ::close(pipe_ends[1]);
    // Xvfb writes the display number once it accepts connections.
    std::string number;
    pollfd ready{pipe_ends[0], POLLIN, 0};
    char c = 0;
    while (::poll(&ready, 1, 10000) > 0 && ::read(pipe_ends[0], &c, 1) == 1 && c != '\n') {
        number += c;
    }
    ::close(pipe_ends[0]);
    if (number.empty()) {
        ADD_FAILURE() << "Xvfb did not start";
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
        pid_ = -1;
        return;
    }
    name_ = ":" + number;
}

XDisplay::~XDisplay() {
    stop();
}

void XDisplay::stop() {
    if (pid_ > 0) {
        ::kill(pid_, SIGTERM);
        ::waitpid(pid_, nullptr, 0);
        pid_ = -1;
    }
}

SpawnedProgram::SpawnedProgram(const std::string& program, const std::vector<std::string>& args,
                               const std::filesystem::path& cwd, const SpawnSettings& settings)
    : err_(cwd / ("." + program + ".stderr")) {
    std::string terminal_name;
    if (settings.terminal_input) {
        terminal_ = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (terminal_ < 0 || ::grantpt(terminal_) != 0 || ::unlockpt(terminal_) != 0) {
            ADD_FAILURE() << "no pseudo-terminal: " << std::strerror(errno);
            return;
        }
        terminal_name = ::ptsname(terminal_);  // NOLINT(concurrency-mt-unsafe)
    }
    std::vector<std::string> argv = {(bin_dir() / program).string()};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<std::string> env = child_environment(settings.display);
    std::vector<char*> arg_pointers = pointers(argv);
    std::vector<char*> env_pointers = pointers(env);
    const std::string folder = cwd.string();
    const std::string err = err_.string();
    pid_ = ::fork();
    if (pid_ == 0) {
        ::setsid();  // the terminal, if any, becomes its own
        // A program left behind by a test that died (a render of years, say) cannot run forever.
        const rlimit cpu{600, 600};
        ::setrlimit(RLIMIT_CPU, &cpu);
        const int input = settings.terminal_input ? ::open(terminal_name.c_str(), O_RDWR)
                                                  : ::open("/dev/null", O_RDONLY);
        ::dup2(input, STDIN_FILENO);
        const int quiet = ::open("/dev/null", O_WRONLY);
        ::dup2(quiet, STDOUT_FILENO);
        const int errors = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(errors, STDERR_FILENO);
        if (::chdir(folder.c_str()) != 0) {
            ::_exit(126);
        }
        ::execve(arg_pointers[0], arg_pointers.data(), env_pointers.data());
        ::_exit(127);
    }
}

SpawnedProgram::~SpawnedProgram() {
    if (pid_ > 0 && !status_) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
    if (terminal_ >= 0) {
        ::close(terminal_);
    }
}

void SpawnedProgram::type_line(const std::string& text) {
    const std::string line = text + "\n";
    ASSERT_EQ(::write(terminal_, line.data(), line.size()), static_cast<ssize_t>(line.size()));
}

void SpawnedProgram::signal(int number) {
    ::kill(pid_, number);
}

std::optional<int> SpawnedProgram::wait_for_exit(std::chrono::milliseconds limit) {
    const auto until = std::chrono::steady_clock::now() + limit * kSlowdown;
    while (!status_ && pid_ > 0) {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            break;
        }
        if (std::chrono::steady_clock::now() > until) {
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return status_;
}

std::string SpawnedProgram::errors() const {
    return std::filesystem::exists(err_) ? read_text(err_) : "";
}

namespace {

Image8 xwd_screenshot(const std::string& display, const std::string& which) {
    const std::string command = "xwd -display '" + display + "' " + which +
                                " -silent 2>/dev/null | convert xwd:- ppm:- 2>/dev/null";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return {};
    }
    std::string bytes;
    std::array<char, 65536> chunk{};
    std::size_t n = 0;
    while ((n = std::fread(chunk.data(), 1, chunk.size(), pipe)) > 0) {
        bytes.append(chunk.data(), n);
    }
    ::pclose(pipe);
    return bytes.empty() ? Image8{} : parse_ppm(bytes);
}

}  // namespace

std::chrono::milliseconds stretched(std::chrono::milliseconds limit) {
    return limit * kSlowdown;
}

Image8 screenshot(const std::string& display, const std::string& title) {
    return xwd_screenshot(display, "-name '" + title + "'");
}

Image8 screenshot_of(const std::string& display, unsigned long id) {
    return xwd_screenshot(display, "-id " + std::to_string(id));
}

bool wait_for_file(const std::filesystem::path& path, std::chrono::milliseconds limit) {
    const auto until = std::chrono::steady_clock::now() + limit * kSlowdown;
    while (!std::filesystem::exists(path)) {
        if (std::chrono::steady_clock::now() > until) {
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return true;
}

}  // namespace rt::test
