// A window on the screen showing a PictureBoard, drawn by a thread of its own so that whoever
// fills the board (the renderer) never waits for the display. The manual's rt opened one "in the
// top left-hand corner of the screen" (1.2.2); docs/window.md says what this one does.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "rt/window/picture_board.h"

namespace rt {

struct WindowRequest {
    std::string title;
    int width = 0;  ///< the view area, in pixels
    int height = 0;
    DisplayMapping mapping;
    /// show: + and - change the exposure (-m) live, 0 restores it, and the title names the pixel
    /// under the cursor with its value.
    bool explore = false;
    /// Called (on the window's own thread) when the viewer closes it: rt stops the render there
    /// as Ctrl-C does, inside the ray tree. May be empty.
    std::function<void()> on_close;
    /// Called (on the window's own thread) when the display goes away under the window: the X
    /// server ended or dropped the connection. Says so ("lost the window: X display ':0'
    /// closed the connection"). rt renders on without the window. May be empty.
    std::function<void(const std::string& why)> on_lost;
};

class PictureWindow {
public:
    virtual ~PictureWindow() = default;
    PictureWindow() = default;
    PictureWindow(const PictureWindow&) = delete;
    PictureWindow& operator=(const PictureWindow&) = delete;

    virtual PictureBoard& board() = 0;
    /// The viewer closed the window or pressed Esc or Ctrl-C in it.
    virtual bool closed() const = 0;
    /// The display went away: nothing is shown any more (WindowRequest::on_lost).
    virtual bool lost() const = 0;
};

/// True when this build can open windows (SDL2 was found: RT_WITH_WINDOW).
bool windows_available();

/// Opens the window, or returns null with the reason in `why_not` when there is no display
/// (DISPLAY and WAYLAND_DISPLAY unset, or the display cannot be reached) or no window support.
std::unique_ptr<PictureWindow> open_picture_window(const WindowRequest& request,
                                                   std::string& why_not);

/// Returns when a line is read from file descriptor `fd` (the viewer pressed Enter, or the input
/// ended), the window is closed or lost, or `stop` says so (Ctrl-C).
void wait_for_enter_or_close(const PictureWindow& window, int fd,
                             const std::function<bool()>& stop);

}  // namespace rt
