// Ctrl-C: the first press asks the render to stop and keep what it finished; a second press
// ends the program at once.
#pragma once

namespace rt {

void install_interrupt_handler();
bool interrupt_requested();

}  // namespace rt
