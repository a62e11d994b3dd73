// The window, with SDL2. One thread does everything SDL (initialisation, events, drawing), as
// SDL's video functions want; the others only touch the PictureBoard and the atomic flags. SDL's
// functions come from sdl_functions(), which loads libSDL2 only when a window is wanted.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <future>
#include <mutex>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "rt/core/available_memory.h"
#include "rt/core/error.h"
#include "rt/window/picture_window.h"
#include "rt/window/sdl/sdl_functions.h"
#include "rt/window/sdl/x_connection_watch.h"

#include <fmt/format.h>

#include <SDL.h>

#ifndef __has_feature
#define __has_feature(x) 0  // GCC 12 has no __has_feature; it says __SANITIZE_ADDRESS__ instead
#endif
#if defined(__SANITIZE_ADDRESS__) || __has_feature(address_sanitizer)
#include <sanitizer/lsan_interface.h>
#define RT_LEAK_SANITIZER 1
#endif

namespace rt {

namespace {

bool set(const char* variable) {
    const char* value = std::getenv(variable);  // NOLINT(concurrency-mt-unsafe): read only
    return value != nullptr && *value != '\0';
}

// The SDL video drivers for the display the environment names ("" when it names none): SDL
// would otherwise try every driver it has, and asking costs time rt should spend rendering.
const char* driver_named() {
    if (set("SDL_VIDEODRIVER")) {
        return std::getenv("SDL_VIDEODRIVER");  // NOLINT(concurrency-mt-unsafe): read only
    }
    if (set("WAYLAND_DISPLAY")) {
        return set("DISPLAY") ? "wayland,x11" : "wayland";
    }
    return set("DISPLAY") ? "x11" : "";
}

// Why SDL could not open a window, naming the display it tried (a mistyped DISPLAY shows).
std::string no_window_on_display(const char* why) {
    const char* display = std::getenv("DISPLAY");  // NOLINT(concurrency-mt-unsafe): read only
    const char* wayland = std::getenv("WAYLAND_DISPLAY");  // NOLINT(concurrency-mt-unsafe)
    std::string where;
    if (wayland != nullptr && *wayland != '\0') {
        where = fmt::format(" on Wayland display '{}'", wayland);
    }
    if (display != nullptr && *display != '\0') {
        where += fmt::format("{} X display '{}'", where.empty() ? " on" : " or", display);
    }
    return fmt::format("no window{}: {}", where, why);
}

constexpr std::uint32_t kFrameMilliseconds = 16;  // about 60 redraws a second, at most
constexpr int kEventsPerFrame = 256;              // handled before each frame, at most
// The whole picture is drawn again this often, changed or not: a draw made before the X server
// mapped the window is lost without an expose event on some servers (Xvfb without a window
// manager, under load), and only this brings the unchanged rows (the wireframe) back. A blit of
// the mapped picture costs far less than a frame.
constexpr std::uint32_t kWholeRedrawMilliseconds = 250;
constexpr double kExposureStep = std::numbers::sqrt2;  // half a stop per key press

bool is_close_key(const SDL_Keysym& key) {
    return key.sym == SDLK_ESCAPE || (key.sym == SDLK_c && (key.mod & KMOD_CTRL) != 0);
}

class SdlPictureWindow : public PictureWindow {
public:
    SdlPictureWindow(const SdlFunctions& sdl, const WindowRequest& request)
        : sdl_(sdl), request_(request), board_(request.width, request.height, request.mapping) {}

    ~SdlPictureWindow() override {
        stopping_ = true;
        if (!thread_.joinable()) {
            return;
        }
        std::unique_lock lock(thread_state_mutex_);
        thread_state_changed_.wait(lock, [this] { return thread_done_ || lost_; });
        if (thread_done_) {
            lock.unlock();
            thread_.join();
        } else {
            thread_.detach();  // it stays in Xlib's error handler for good (x_connection_watch.h)
        }
    }

    // Starts the thread and waits until it has a window (empty answer) or has failed.
    std::string start() {
        std::promise<std::string> opened;
        std::future<std::string> answer = opened.get_future();
        thread_ = std::thread([this, &opened] {
            run(opened);
            const std::lock_guard lock(thread_state_mutex_);
            thread_done_ = true;
            thread_state_changed_.notify_all();
        });
        return answer.get();
    }

    PictureBoard& board() override { return board_; }
    bool closed() const override { return closed_; }
    bool lost() const override { return lost_; }

private:
    // SDL, and the dbus and X11 libraries it loads (and unloads in SDL_Quit), leave a few small
    // blocks at exit; their stacks end in unloaded modules that no suppression file can name
    // (cmake/sanitizer-suppressions/lsan.supp). So LeakSanitizer ignores what this thread
    // allocates: it only runs SDL and draws.
    struct ThirdPartyLeaksIgnored {
#ifdef RT_LEAK_SANITIZER
        ThirdPartyLeaksIgnored() {
            __lsan_disable();
        }
        ~ThirdPartyLeaksIgnored() {
            __lsan_enable();
        }
#else
        ThirdPartyLeaksIgnored() = default;
#endif
        ThirdPartyLeaksIgnored(const ThirdPartyLeaksIgnored&) = delete;
        ThirdPartyLeaksIgnored& operator=(const ThirdPartyLeaksIgnored&) = delete;
    };

    void run(std::promise<std::string>& opened) {
        [[maybe_unused]] const ThirdPartyLeaksIgnored sdl_leaks;
        // rt keeps its own Ctrl-C handler (app/interrupt.cpp): SDL must not take SIGINT.
        sdl_.SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        // Only the display named; SDL would otherwise fall back to other drivers (offscreen,
        // KMS) that show nothing to anyone.
        sdl_.SDL_SetHint(SDL_HINT_VIDEODRIVER, driver_named());
        // SDL would draw the window's surface through OpenGL (on a display without a GPU, Mesa's
        // llvmpipe, with threads of its own), for pictures rt only copies. X's own images do it;
        // and OpenGL's exit code waits for a display lock that a broken connection never frees.
        sdl_.SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
        if (sdl_.SDL_Init(SDL_INIT_VIDEO) != 0) {
            opened.set_value(no_window_on_display(sdl_.SDL_GetError()));
            sdl_.SDL_Quit();  // what SDL_Init set up before it failed, so that a retry starts clean
            return;
        }
        const char* driver = sdl_.SDL_GetCurrentVideoDriver();
        if (driver != nullptr && std::strcmp(driver, "x11") == 0) {
            opening_ = &opened;
            watch_x_connection([this] { connection_lost(); });
        }
        window_ = sdl_.SDL_CreateWindow(request_.title.c_str(), 0, 0, request_.width,
                                        request_.height, SDL_WINDOW_SHOWN);
        if (window_ == nullptr) {
            opening_ = nullptr;
            opened.set_value(fmt::format("no window: {}", sdl_.SDL_GetError()));
            sdl_.SDL_Quit();
            stop_watching_x_connection();
            return;
        }
        opening_ = nullptr;
        opened.set_value("");
        loop();
        sdl_.SDL_DestroyWindow(window_);
        sdl_.SDL_Quit();
        stop_watching_x_connection();
    }

    // The X server went away (on this thread, in an SDL call; x_connection_watch.h): the window
    // says so, or the opening fails, and this thread never returns.
    void connection_lost() {
        if (opening_ != nullptr) {
            opening_->set_value(no_window_on_display("the X server closed the connection"));
            opening_ = nullptr;
        } else if (request_.on_lost) {
            const char* display = std::getenv("DISPLAY");  // NOLINT(concurrency-mt-unsafe)
            request_.on_lost(fmt::format("lost the window: X display '{}' closed the connection",
                                         display != nullptr ? display : ""));
        }
        const std::lock_guard lock(thread_state_mutex_);
        lost_ = true;
        thread_state_changed_.notify_all();
    }

    void loop() {
        std::vector<std::uint8_t> rgb;
        bool redraw = true;
        std::uint32_t last_whole = sdl_.SDL_GetTicks();
        std::uint32_t last_frame = last_whole;
        while (!stopping_) {
            SDL_Event event;
            const std::uint32_t since_frame = sdl_.SDL_GetTicks() - last_frame;
            if (since_frame < kFrameMilliseconds &&
                sdl_.SDL_WaitEventTimeout(
                    &event, static_cast<int>(kFrameMilliseconds - since_frame)) != 0) {
                redraw = handle(event) || redraw;
                continue;  // until the frame is due, events come first
            }
            // The frame is due. A steady stream of events (a pointer moving over the window, an
            // X server replaying a backlog) must not hold it back: only those queued now are
            // taken, and at most kEventsPerFrame of them.
            for (int taken = 0; taken < kEventsPerFrame && sdl_.SDL_PollEvent(&event) != 0;
                 ++taken) {
                redraw = handle(event) || redraw;
            }
            PictureBoard::Rows rows = board_.update(rgb);
            const std::uint32_t now = sdl_.SDL_GetTicks();
            last_frame = now;
            if (redraw || now - last_whole >= kWholeRedrawMilliseconds) {
                rows = {0, board_.height() - 1};
                last_whole = now;
            }
            if (rows.top <= rows.bottom && !closed_) {
                draw(rgb, rows);
                redraw = false;
            }
        }
    }

    // True when the window must be drawn again.
    bool handle(const SDL_Event& event) {
        switch (event.type) {
            case SDL_QUIT:
                close();
                return false;
            case SDL_WINDOWEVENT:
                if (event.window.event == SDL_WINDOWEVENT_CLOSE) {
                    close();
                    return false;
                }
                return event.window.event == SDL_WINDOWEVENT_EXPOSED ||
                       event.window.event == SDL_WINDOWEVENT_SHOWN ||
                       event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED;
            case SDL_KEYDOWN:
                if (is_close_key(event.key.keysym)) {
                    close();
                } else if (request_.explore) {
                    change_exposure(event.key.keysym.sym);
                }
                return false;
            case SDL_MOUSEMOTION:
                if (request_.explore) {
                    cursor_x_ = event.motion.x;
                    cursor_y_ = event.motion.y;
                    update_title();
                }
                return false;
            default:
                return false;
        }
    }

    void close() {
        closed_ = true;
        sdl_.SDL_HideWindow(window_);
        if (request_.on_close) {
            request_.on_close();
        }
    }

    void change_exposure(SDL_Keycode key) {
        DisplayMapping m = board_.mapping();
        if (key == SDLK_PLUS || key == SDLK_KP_PLUS || key == SDLK_EQUALS) {
            m.multiplier *= kExposureStep;
        } else if (key == SDLK_MINUS || key == SDLK_KP_MINUS) {
            m.multiplier /= kExposureStep;
        } else if (key == SDLK_0 || key == SDLK_KP_0) {
            m.multiplier = request_.mapping.multiplier;
        } else {
            return;
        }
        board_.set_mapping(m);
        update_title();
    }

    // "NAME  -m1.41  (x, y) = r g b": the exposure, and the linear value under the cursor.
    void update_title() {
        std::string title =
            fmt::format("{}  -m{:.3g}", request_.title, board_.mapping().multiplier);
        if (cursor_x_ >= 0 && cursor_x_ < board_.width() && cursor_y_ >= 0 &&
            cursor_y_ < board_.height()) {
            const Rgb v = board_.pixel(cursor_x_, cursor_y_);
            title += fmt::format("  ({}, {}) = {:.4g} {:.4g} {:.4g}", cursor_x_, cursor_y_, v.r,
                                 v.g, v.b);
        }
        sdl_.SDL_SetWindowTitle(window_, title.c_str());
    }

    // Only the rows that changed go to the display: a render changes a few rows a frame.
    void draw(std::vector<std::uint8_t>& rgb, const PictureBoard::Rows& rows) {
        SDL_Surface* screen = sdl_.SDL_GetWindowSurface(window_);
        SDL_Surface* picture =
            sdl_.SDL_CreateRGBSurfaceWithFormatFrom(rgb.data(), board_.width(), board_.height(), 24,
                                                    board_.width() * 3, SDL_PIXELFORMAT_RGB24);
        if (screen != nullptr && picture != nullptr) {
            SDL_Rect band{0, rows.top, board_.width(), rows.bottom - rows.top + 1};
            SDL_Rect to = band;
            sdl_.SDL_UpperBlit(picture, &band, screen, &to);  // what SDL_BlitSurface names
            sdl_.SDL_UpdateWindowSurfaceRects(window_, &band, 1);
        }
        sdl_.SDL_FreeSurface(picture);
    }

    const SdlFunctions& sdl_;
    WindowRequest request_;
    PictureBoard board_;
    std::thread thread_;
    SDL_Window* window_ = nullptr;
    std::atomic<bool> stopping_{false};
    std::atomic<bool> closed_{false};
    std::promise<std::string>* opening_ = nullptr;  // until the opening is answered
    // The thread ends (thread_done_) or stays in Xlib's error handler for good (lost_): the
    // destructor joins it, or lets it go.
    std::mutex thread_state_mutex_;
    std::condition_variable thread_state_changed_;
    bool thread_done_ = false;
    std::atomic<bool> lost_{false};
    int cursor_x_ = -1;
    int cursor_y_ = -1;
};

}  // namespace

bool windows_available() {
    return true;
}

std::unique_ptr<PictureWindow> open_picture_window(const WindowRequest& request,
                                                   std::string& why_not) {
    if (*driver_named() == '\0') {
        why_not = "no display (DISPLAY is not set)";
        return nullptr;
    }
    why_not = window_memory_refusal(request.width, request.height, available_memory());
    if (!why_not.empty()) {
        return nullptr;  // before the board takes any of it
    }
    const SdlFunctions* sdl = nullptr;
    try {
        sdl = &sdl_functions();  // loaded only now, when a window is wanted on a display
    } catch (const Error& e) {
        why_not = fmt::format("no window: {}", e.what());  // as when SDL_Init fails
        return nullptr;
    }
    // A display that is there can still refuse a connection for a moment: the window tests saw
    // rt find no window on an Xvfb that had served other clients for seconds, twice in a few
    // dozen runs on a loaded machine. A window asked for is worth two more tries; a display that
    // is not there costs 300 ms more before rt renders headless.
    constexpr int kAttempts = 3;
    constexpr auto kPause = std::chrono::milliseconds(150);
    for (int attempt = 1;; ++attempt) {
        auto window = std::make_unique<SdlPictureWindow>(*sdl, request);
        why_not = window->start();
        if (why_not.empty()) {
            return window;
        }
        if (attempt == kAttempts || window->lost()) {  // a server gone is not asked again
            return nullptr;
        }
        std::this_thread::sleep_for(kPause);
    }
}

}  // namespace rt
