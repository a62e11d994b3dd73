#include "rt/app/interrupt.h"

#include <atomic>
#include <csignal>

#include <unistd.h>

namespace rt {

namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_interrupt(int signal) {
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

}  // namespace rt
