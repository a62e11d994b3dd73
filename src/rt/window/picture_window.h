// A window on the screen showing a PictureBoard, drawn by a thread of its own so that whoever
// fills the board (the renderer) never waits for the display. The manual's rt opened one "in the
// top left-hand corner of the screen" (1.2.2); docs/window.md says what this one does.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "rt/core/available_memory.h"
#include "rt/window/picture_board.h"

namespace rt {

/// What a window holds for each pixel of its view: the linear picture the board keeps, a film
/// drawn into it (rt's wireframe), the 8-bit copies the display thread maps and SDL's surface.
/// rt's peak memory grows 31 bytes a view pixel from a 2048 x 2048 to a 4096 x 4096 view with the
/// window open on Xvfb (docs/lab/window-2026-12-04.md).
constexpr std::uint64_t kWindowBytesPerViewPixel = 32;

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

/// Why a window of `width` x `height` pixels cannot open in the memory `limit` leaves
/// (kWindowBytesPerViewPixel each): "no window: one of 16000 x 16000 pixels needs about 7.6 GiB,
/// more than the 3.8 GiB available (...)"; empty when it fits or no limit is known. A .gro may
/// name a view of 16384 x 16384 pixels for a window of 10 x 10.
std::string window_memory_refusal(int width, int height, const std::optional<MemoryLimit>& limit);

/// True when this build can open windows (SDL2 was found: RT_WITH_WINDOW).
bool windows_available();

/// Opens the window, or returns null with the reason in `why_not` when there is no display
/// (DISPLAY and WAYLAND_DISPLAY unset, or the display cannot be reached), no window support, or
/// not memory enough for a window of that view (kWindowBytesPerViewPixel, checked before any of
/// it is allocated).
std::unique_ptr<PictureWindow> open_picture_window(const WindowRequest& request,
                                                   std::string& why_not);

/// Returns when a line is read from file descriptor `fd` (the viewer pressed Enter, or the input
/// ended), the window is closed or lost, or `stop` says so (Ctrl-C).
void wait_for_enter_or_close(const PictureWindow& window, int fd,
                             const std::function<bool()>& stop);

}  // namespace rt
