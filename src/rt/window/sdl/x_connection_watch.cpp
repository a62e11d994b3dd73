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

// XSetIOErrorHandler from libX11 as SDL loaded it; null when it cannot be found. SDL unloads
// libX11 in SDL_Quit: the handle kept here keeps it (and the handler rt sets in it) in place for
// the rest of the run.
decltype(&::XSetIOErrorHandler) x11_set_handler() {
    static const auto set_handler = []() -> decltype(&::XSetIOErrorHandler) {
        try {
            static const SharedLibrary* const x11 = new SharedLibrary("libX11.so.6");
            return x11->function<decltype(::XSetIOErrorHandler)>("XSetIOErrorHandler");
        } catch (const Error&) {
            return nullptr;
        }
    }();
    return set_handler;
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
    const auto set_handler = x11_set_handler();
    if (set_handler == nullptr) {
        return false;
    }
    Watch& watch = the_watch();
    const std::lock_guard lock(watch.mutex);
    if (!watch.installed) {
        watch.previous = set_handler(on_connection_broken);
        watch.installed = true;
    }
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
