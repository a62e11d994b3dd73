// When the X server goes away under the window (it ends, crashes, or its connection drops), Xlib
// calls its I/O error handler, and the default one prints a line and ends the process: the render
// and everything it finished would be lost. rt's handler tells the window instead, which lets the
// render go on without it. Xlib ends the process if its handler returns, so the thread the error
// came on never comes back from it: the window's thread, which does nothing but show.
#pragma once

#include <functional>

namespace rt {

/// Watches the X connection SDL's x11 driver opened, from the thread that calls this (the one
/// that makes every SDL call). When the connection breaks in a call on that thread, `on_lost` runs
/// there, once, and the thread then waits for good: its owner must not wait for it to end. A
/// broken connection on any other thread ends the process as Xlib's default does. Requests the
/// server refuses (X protocol errors) are dropped rather than ending the process. False when
/// libX11 is not loaded (SDL uses another driver): nothing is watched.
bool watch_x_connection(std::function<void()> on_lost);

/// Stops watching (after SDL_Quit, which closes the connection and may find it broken).
void stop_watching_x_connection();

}  // namespace rt
