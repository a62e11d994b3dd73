// rt SCENE [switches]: renders a CMU RayTracer scene. Parses the command line, runs the library,
// and turns errors into one-line messages and exit codes (docs/usage.md).
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "rt/app/help.h"
#include "rt/app/interrupt.h"
#include "rt/app/run.h"
#include "rt/app/switch_parser.h"
#include "rt/core/error.h"

#include <unistd.h>

namespace {

// The exit status, one per kind of failure (the README lists them).
constexpr int kOk = 0;
constexpr int kBadInput = 1;
constexpr int kUsage = 2;
constexpr int kIo = 3;
constexpr int kInternal = 4;
constexpr int kInterrupted = 130;

void print_line(const std::string& line) {
    std::cerr << line << '\n';
}

// A progress line on a terminal, at most every quarter second.
std::function<void(int, int)> progress_printer(bool quiet) {
    if (quiet || ::isatty(STDERR_FILENO) == 0) {
        return {};
    }
    auto last = std::make_shared<std::chrono::steady_clock::time_point>();
    return [last](int done, int total) {
        const auto now = std::chrono::steady_clock::now();
        if (done < total && now - *last < std::chrono::milliseconds(250)) {
            return;
        }
        *last = now;
        std::cerr << "\rrt: " << done << " of " << total << " lines" << (done == total ? "\n" : "")
                  << std::flush;
    };
}

rt::RunConsole make_console(const rt::Options& options) {
    rt::RunConsole console;
    console.warning = [](const std::string& m) { print_line("rt: warning: " + m); };
    console.note = [quiet = options.quiet](const std::string& m) {
        if (!quiet) {
            print_line("rt: " + m);
        }
    };
    console.trace = print_line;
    console.report = [](const std::string& text) { std::fputs(text.c_str(), stdout); };
    console.progress = progress_printer(options.quiet);
    console.should_stop = rt::interrupt_requested;
    return console;
}

int run(const std::vector<std::string>& args) {
    const rt::Options options = rt::parse_command_line(args);
    if (options.show_usage) {
        std::cout << rt::usage_text();
        return kOk;
    }
    if (options.show_help) {
        std::cout << rt::help_text();
        return kOk;
    }
    if (options.show_version) {
        std::cout << rt::version_text() << '\n';
        return kOk;
    }
    rt::install_interrupt_handler();
    if (rt::run(options, make_console(options)) == rt::RunOutcome::Interrupted) {
        print_line("rt: interrupted; the finished lines were written");
        return kInterrupted;
    }
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const rt::InputError& e) {
        print_line(e.what());
        return kBadInput;
    } catch (const rt::SettingError& e) {
        // The library names settings; say which switch sets each.
        print_line("rt: " + rt::name_the_switches(e.what()));
        print_line("rt: run 'rt --help' for the list of switches");
        return kUsage;
    } catch (const rt::UsageError& e) {
        print_line(std::string("rt: ") + e.what());
        print_line("rt: run 'rt --help' for the list of switches");
        return kUsage;
    } catch (const rt::NotImplementedError& e) {
        print_line(std::string("rt: ") + e.what());
        return kUsage;
    } catch (const rt::IoError& e) {
        print_line(std::string("rt: ") + e.what());
        return kIo;
    } catch (const std::exception& e) {
        print_line(std::string("rt: internal error: ") + e.what());
        return kInternal;
    }
}
