// rt SCENE [switches]: renders a CMU RayTracer scene. Parses the command line, runs the library,
// and turns errors into one-line messages and exit codes (docs/usage.md).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "rt/app/help.h"
#include "rt/app/interrupt.h"
#include "rt/app/progress_report.h"
#include "rt/app/run.h"
#include "rt/app/switch_parser.h"
#include "rt/core/error.h"
#ifdef RT_WITH_MPI
#include "rt/cluster/cluster_error.h"
#include "rt/cluster/cluster_run.h"
#include "rt/cluster/mpi_world.h"
#endif

#include <unistd.h>

namespace {

// The exit status, one per kind of failure (the README lists them).
constexpr int kOk = 0;
constexpr int kBadInput = 1;
constexpr int kUsage = 2;
constexpr int kIo = 3;
constexpr int kInternal = 4;
constexpr int kClusterFailure = 5;  // a rank of an MPI job failed or was stopped
constexpr int kInterrupted = 130;

// Set once the command line has turned out to be one that rank 0 of the same MPI job reports.
bool quiet_failure = false;

void print_line(const std::string& line) {
    if (!quiet_failure) {
        std::cerr << line << '\n';
    }
}

// Under mpirun every rank reads the same command line before MPI starts: rank 0 alone reports
// what is wrong with it, or prints the help, so that a job of 64 ranks says it once
// (docs/distributed.md). Later failures are a rank's own, and go to rank 0 through MPI.
bool another_rank_speaks() {
#ifdef RT_WITH_MPI
    const std::optional<int> rank = rt::cluster::launcher_rank();
    return rank.has_value() && *rank != 0;
#else
    return false;
#endif
}

// A rank that stays quiet about a bad command line lets rank 0 say it first. mpirun ends the whole
// job at the first rank that exits non-zero: a quiet rank that ended at once could cut rank 0 off
// before it printed a word. So the quiet rank waits for the launcher to end the job when rank 0
// exits; the bound ends the wait where rank 0's command line was good (an MPMD job given this rank
// alone a bad switch) and rank 0 waits on this rank instead.
constexpr std::chrono::seconds kQuietRankWait{10};

// The command line, or the exception that says what is wrong with it, said by rank 0 alone.
rt::Options read_command_line(int argc, char** argv) {
    try {
        return rt::parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
    } catch (...) {
        quiet_failure = another_rank_speaks();
        throw;
    }
}

double steady_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Progress on standard error: a bar on a terminal, a line every few seconds elsewhere, nothing
// with --quiet.
std::unique_ptr<rt::ProgressReport> make_progress(const rt::Options& options) {
    if (options.quiet) {
        return nullptr;
    }
    const auto style = ::isatty(STDERR_FILENO) != 0 ? rt::ProgressReport::Style::Bar
                                                    : rt::ProgressReport::Style::Lines;
    return std::make_unique<rt::ProgressReport>(std::cerr, style, steady_seconds);
}

// Every message goes through the progress report, so that none lands in the middle of the bar.
rt::RunConsole make_console(const rt::Options& options, rt::ProgressReport* progress) {
    const std::function<void(const std::string&)> line = [progress](const std::string& text) {
        if (progress != nullptr) {
            progress->print_line(text);
        } else {
            print_line(text);
        }
    };
    rt::RunConsole console;
    console.warning = [line](const std::string& m) { line("rt: warning: " + m); };
    console.note = [line, quiet = options.quiet](const std::string& m) {
        if (!quiet) {
            line("rt: " + m);
        }
    };
    console.trace = line;
    console.report = [](const std::string& text) { std::fputs(text.c_str(), stdout); };
    if (progress != nullptr) {
        console.progress = [progress](int done, int total, std::uint64_t samples) {
            progress->update(done, total, samples);
        };
    }
    console.should_stop = rt::interrupt_requested;
    console.stop_now = &rt::interrupt_flag();
    // -doi reads its commands here; a prompt only for a person typing them.
    console.commands = &std::cin;
    console.answers = &std::cout;
    console.prompt = ::isatty(STDIN_FILENO) != 0 ? "octree> " : "";
    if (!options.no_window) {
        console.open_window = [warn = console.warning](const rt::WindowRequest& request) {
            std::string why_not;
            rt::WindowRequest stopping = request;
            stopping.on_close = rt::request_interrupt;  // closing it stops the render at once
            // The finished lines are the render's, not the window's: they stay, and so does rt.
            stopping.on_lost = [warn](const std::string& why) {
                warn(why + "; rt goes on without it");
            };
            std::unique_ptr<rt::PictureWindow> window = rt::open_picture_window(stopping, why_not);
            if (!window && std::getenv("DISPLAY") != nullptr) {  // NOLINT(concurrency-mt-unsafe)
                // A display was named but cannot be reached: the user expected a window, so this
                // is said even under --quiet.
                warn(why_not);
            }
            return window;
        };
    }
    // Manual 1.2.2: "When the picture is completed, the program waits for you to type a carriage
    // return". Only a person at a terminal can; otherwise the window closes by itself.
    if (::isatty(STDIN_FILENO) != 0) {
        console.keep_window_open = [note = console.note](const rt::PictureWindow& window) {
            note("the picture is written; press Enter (or close the window) to finish");
            rt::wait_for_enter_or_close(window, STDIN_FILENO, rt::interrupt_requested);
        };
    }
    return console;
}

int run(int argc, char** argv) {
    const rt::Options options = read_command_line(argc, argv);
    if (options.show_usage || options.show_help || options.show_version) {
        if (another_rank_speaks()) {
            return kOk;
        }
        if (options.show_usage) {
            std::cout << rt::usage_text();
        } else if (options.show_help) {
            std::cout << rt::help_text();
        } else {
            std::cout << rt::version_text() << '\n';
        }
        return kOk;
    }
    rt::install_interrupt_handler();
    const std::unique_ptr<rt::ProgressReport> progress = make_progress(options);
    const rt::RunConsole console = make_console(options, progress.get());
#ifdef RT_WITH_MPI
    // Under mpirun, every process runs this; rank 0 alone prints, renders with the others and
    // writes (docs/distributed.md).
    const rt::RunOutcome outcome = rt::cluster::started_by_mpi_launcher()
                                       ? rt::cluster::run_in_cluster(options, console, argc, argv)
                                       : rt::run(options, console);
#else
    const rt::RunOutcome outcome = rt::run(options, console);
#endif
    if (outcome != rt::RunOutcome::Finished) {
        console.trace(outcome == rt::RunOutcome::Interrupted  // printed as is
                          ? "rt: interrupted; the finished lines are kept"
                          : "rt: interrupted");
        // The shell's convention: 128 + the signal (130 for Ctrl-C, 143 for SIGTERM); a window
        // closed by the user counts as Ctrl-C.
        const int signal = rt::interrupt_signal();
        return signal != 0 ? 128 + signal : kInterrupted;
    }
    return kOk;
}

int run_and_report(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const rt::InputError& e) {
        print_line(e.what());
        return kBadInput;
#ifdef RT_WITH_MPI
    } catch (const rt::cluster::ClusterError& e) {
        print_line(std::string("rt: ") + e.what());
        return kClusterFailure;
#endif
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
    } catch (const std::bad_alloc&) {
        // The estimate before the render (--max-memory) missed something, or memory went away.
        print_line(
            "rt: out of memory: ask for less (a smaller view area or output matrix, smaller "
            "texture pictures), or close other programs");
        return kInternal;
    } catch (const std::exception& e) {
        print_line(std::string("rt: internal error: ") + e.what());
        return kInternal;
    }
}
}  // namespace

int main(int argc, char** argv) {
    const int status = run_and_report(argc, argv);
    if (quiet_failure) {
        std::this_thread::sleep_for(kQuietRankWait);
    }
    return status;
}
