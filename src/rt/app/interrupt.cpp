#include "rt/app/interrupt.h"

#include <atomic>
#include <csignal>

#include <unistd.h>

namespace rt {

namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");
std::atomic<int> g_signal{0};  // the first signal received

extern "C" void on_interrupt(int signal) {
    int none = 0;
    g_signal.compare_exchange_strong(none, signal);
    if (g_interrupted.exchange(true)) {
        // A second Ctrl-C: the user really wants out.
        ::_exit(128 + signal);
    }
}

}  // namespace

void install_interrupt_handler() {
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
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

}  // namespace rt
