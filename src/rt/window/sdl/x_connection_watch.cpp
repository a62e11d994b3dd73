#include "rt/window/sdl/x_connection_watch.h"

#include <chrono>
#include <mutex>
#include <thread>
#include <utility>

#include "rt/core/error.h"
#include "rt/core/shared_library.h"

#include <X11/Xlib.h>

namespace rt {

namespace {

struct Watch {
    std::mutex mutex;
    std::thread::id thread;  // the watched one; none when nothing is watched
    std::function<void()> on_lost;
    XIOErrorHandler previous = nullptr;  // Xlib's default, or whoever set one before rt
    bool installed = false;
};

Watch& the_watch() {
    static Watch* const watch = new Watch;  // never destroyed: a handler may run during exit
    return *watch;
}

// Xlib's two handler setters from libX11 as SDL loaded it; null when they cannot be found. SDL
// unloads libX11 in SDL_Quit: the handle kept here keeps it (and the handlers rt sets in it) in
// place for the rest of the run.
struct HandlerSetters {
    decltype(&::XSetIOErrorHandler) io = nullptr;
    decltype(&::XSetErrorHandler) protocol = nullptr;
};
const HandlerSetters& x11_handler_setters() {
    static const HandlerSetters setters = [] {
        try {
            static const SharedLibrary* const x11 = new SharedLibrary("libX11.so.6");
            return HandlerSetters{
                x11->function<decltype(::XSetIOErrorHandler)>("XSetIOErrorHandler"),
                x11->function<decltype(::XSetErrorHandler)>("XSetErrorHandler")};
        } catch (const Error&) {
            return HandlerSetters{};
        }
    }();
    return setters;
}

// A request the server refused (an X protocol error). Xlib's default handler prints it and ends
// the process; SDL's chains to it. The ones SDL's requests can meet are SDL's own races, and SDL
// says there is nothing to do about them: its wake-up message goes to the window on a second
// connection, and reaches the server after the window is destroyed when the viewer closes it at
// that moment (BadWindow on X_SendEvent, seen ending show with status 1). No window is worth
// ending a render for: the error is dropped.
int on_request_refused(Display* /*display*/, XErrorEvent* /*error*/) {
    return 0;
}

int on_connection_broken(Display* display) {
    Watch& watch = the_watch();
    std::function<void()> on_lost;
    XIOErrorHandler previous = nullptr;
    {
        const std::lock_guard lock(watch.mutex);
        if (watch.thread == std::this_thread::get_id()) {
            on_lost = std::move(watch.on_lost);
            watch.thread = {};
        }
        previous = watch.previous;
    }
    if (!on_lost) {
        return previous != nullptr ? previous(display) : 0;  // Xlib ends the process after this
    }
    on_lost();
    for (;;) {
        std::this_thread::sleep_for(std::chrono::hours(1));
    }
}

}  // namespace

bool watch_x_connection(std::function<void()> on_lost) {
    const HandlerSetters& set = x11_handler_setters();
    if (set.io == nullptr || set.protocol == nullptr) {
        return false;
    }
    Watch& watch = the_watch();
    const std::lock_guard lock(watch.mutex);
    if (!watch.installed) {
        watch.previous = set.io(on_connection_broken);
        watch.installed = true;
    }
    set.protocol(on_request_refused);  // after SDL_Init, which sets its own each time
    watch.thread = std::this_thread::get_id();
    watch.on_lost = std::move(on_lost);
    return true;
}

void stop_watching_x_connection() {
    Watch& watch = the_watch();
    const std::lock_guard lock(watch.mutex);
    watch.thread = {};
    watch.on_lost = nullptr;
}

}  // namespace rt
