// Ctrl-C (SIGINT) or SIGTERM: the first asks the render to stop and keep what it finished; a
// second ends the program at once.
#pragma once

#include <atomic>

namespace rt {

void install_interrupt_handler();
bool interrupt_requested();
/// The flag the first signal sets, for a render to poll cheaply wherever it is.
const std::atomic<bool>& interrupt_flag();
/// Asks to stop as the first Ctrl-C does, without a signal (the picture's window was closed).
void request_interrupt();
/// The signal that asked to stop (SIGINT or SIGTERM); 0 if none did.
int interrupt_signal();

}  // namespace rt
