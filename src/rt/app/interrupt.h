// Ctrl-C (SIGINT) or SIGTERM: the first asks the render to stop and keep what it finished; a
// second ends the program at once, and so does the first before there is anything to keep.
#pragma once

#include <atomic>

namespace rt {

/// Also ignores SIGPIPE: a closed pipe on standard error must not lose a render.
void install_interrupt_handler();
bool interrupt_requested();
/// The flag the first signal sets, for a render to poll cheaply wherever it is.
const std::atomic<bool>& interrupt_flag();
/// Asks to stop as the first Ctrl-C does, without a signal (the picture's window was closed).
void request_interrupt();
/// The signal that asked to stop (SIGINT or SIGTERM); 0 if none did.
int interrupt_signal();

/// While one lives (reading the scene, building the intersection method), the first signal
/// ends the program at once, with 128 + the signal: nothing is finished yet to keep, and a read
/// blocked on a pipe or a long build would never look at the flag.
class ExitOnInterrupt {
public:
    ExitOnInterrupt();
    ~ExitOnInterrupt();
    ExitOnInterrupt(const ExitOnInterrupt&) = delete;
    ExitOnInterrupt& operator=(const ExitOnInterrupt&) = delete;
};

}  // namespace rt
