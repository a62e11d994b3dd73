#include "rt/app/interrupt.h"

#include <atomic>
#include <csignal>

#include <unistd.h>

namespace rt {

namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");
std::atomic<int> g_signal{0};             // the first signal received
std::atomic<bool> g_exit_at_once{false};  // an ExitOnInterrupt lives

[[noreturn]] void exit_interrupted(int signal) {
    static constexpr char kSaid[] = "rt: interrupted\n";
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, kSaid, sizeof kSaid - 1);
    ::_exit(128 + (signal != 0 ? signal : SIGINT));  // a closed window counts as Ctrl-C
}

extern "C" void on_interrupt(int signal) {
    int none = 0;
    g_signal.compare_exchange_strong(none, signal);
    if (g_interrupted.exchange(true) || g_exit_at_once.load()) {
        // A second Ctrl-C (the user really wants out), or nothing finished yet to keep.
        exit_interrupted(signal);
    }
}

}  // namespace

void install_interrupt_handler() {
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    // A reader of the messages that goes away (`rt ... 2>&1 | head -1`) must not end the render:
    // the messages after it are lost (a write then fails with EPIPE), the picture is not.
    std::signal(SIGPIPE, SIG_IGN);
}

bool interrupt_requested() {
    return g_interrupted.load();
}

void request_interrupt() {
    g_interrupted = true;
}

const std::atomic<bool>& interrupt_flag() {
    return g_interrupted;
}

int interrupt_signal() {
    return g_signal.load();
}

ExitOnInterrupt::ExitOnInterrupt() {
    g_exit_at_once = true;
    if (g_interrupted.load()) {  // a signal came just before
        exit_interrupted(g_signal.load());
    }
}

ExitOnInterrupt::~ExitOnInterrupt() {
    g_exit_at_once = false;
}

}  // namespace rt
