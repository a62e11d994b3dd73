// The window tests' display: an Xvfb server started by the test itself (so `ctest` alone runs
// them), programs started on it with a terminal or a file as standard input, and screenshots taken
// with the standard X tools (xwd, then ImageMagick's convert to a PPM).
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rt/image/image8.h"

namespace rt::test {

/// Why the display tests cannot run here (Xvfb, xwd or convert missing); empty when they can.
std::string missing_display_tools();

/// An Xvfb server on a free display number, 24 bits deep; killed when this goes.
class XDisplay {
public:
    XDisplay();  ///< fails the calling test if the server does not start
    ~XDisplay();
    XDisplay(const XDisplay&) = delete;
    XDisplay& operator=(const XDisplay&) = delete;

    const std::string& name() const { return name_; }  ///< ":N"
    bool running() const { return pid_ > 0; }
    /// Ends the server now, as a crash or a closed session would for its clients.
    void stop();

private:
    int pid_ = -1;
    std::string name_;
};

/// How a spawned program gets its display and its standard input.
struct SpawnSettings {
    std::optional<std::string> display;  ///< DISPLAY; none: unset (WAYLAND_DISPLAY too)
    bool terminal_input = false;         ///< a pseudo-terminal (else /dev/null)
};

/// A built program (bin_dir()/program) running in a folder; killed if still running at the end.
class SpawnedProgram {
public:
    SpawnedProgram(const std::string& program, const std::vector<std::string>& args,
                   const std::filesystem::path& cwd, const SpawnSettings& settings);
    ~SpawnedProgram();
    SpawnedProgram(const SpawnedProgram&) = delete;
    SpawnedProgram& operator=(const SpawnedProgram&) = delete;

    /// Types a line on its terminal (terminal_input only).
    void type_line(const std::string& text);
    /// Sends it a signal (SIGINT, as Ctrl-C does).
    void signal(int number);
    /// Its exit status once it exits within `limit` (5 times longer under AddressSanitizer);
    /// none if it is still running then.
    std::optional<int> wait_for_exit(std::chrono::milliseconds limit);
    /// Its standard error so far.
    std::string errors() const;

private:
    int pid_ = -1;
    int terminal_ = -1;  // the pseudo-terminal's controlling side
    std::filesystem::path err_;
    std::optional<int> status_;
};

/// The window titled `title` on `display`, as xwd sees it; an empty picture when there is none.
Image8 screenshot(const std::string& display, const std::string& title);

/// A wait limit stretched as the programs are slowed: 5 times under AddressSanitizer, so that a
/// limit still means "hangs", not "is slow".
std::chrono::milliseconds stretched(std::chrono::milliseconds limit);
/// The same for the window with X id `id` (a title that changes cannot name it).
Image8 screenshot_of(const std::string& display, unsigned long id);

/// Waits (up to `limit`, 5 times longer under AddressSanitizer) until `path` exists.
bool wait_for_file(const std::filesystem::path& path, std::chrono::milliseconds limit);

}  // namespace rt::test
