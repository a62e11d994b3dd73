// The SDL2 functions the window calls, found in libSDL2 the first time a window is wanted rather
// than linked: loading SDL2 and the fifty libraries it needs (X11, Wayland, PulseAudio...) would
// add about 11 ms to every start of rt and show, though most runs open no window.
#pragma once

#include <SDL.h>

namespace rt {

/// Named as SDL names them; each typed from SDL's own header, so that none can drift.
struct SdlFunctions {
    decltype(&::SDL_CreateRGBSurfaceWithFormatFrom) SDL_CreateRGBSurfaceWithFormatFrom = nullptr;
    decltype(&::SDL_CreateWindow) SDL_CreateWindow = nullptr;
    decltype(&::SDL_DestroyWindow) SDL_DestroyWindow = nullptr;
    decltype(&::SDL_FreeSurface) SDL_FreeSurface = nullptr;
    decltype(&::SDL_GetCurrentVideoDriver) SDL_GetCurrentVideoDriver = nullptr;
    decltype(&::SDL_GetError) SDL_GetError = nullptr;
    decltype(&::SDL_GetTicks) SDL_GetTicks = nullptr;
    decltype(&::SDL_GetWindowSurface) SDL_GetWindowSurface = nullptr;
    decltype(&::SDL_HideWindow) SDL_HideWindow = nullptr;
    decltype(&::SDL_Init) SDL_Init = nullptr;
    decltype(&::SDL_PollEvent) SDL_PollEvent = nullptr;
    decltype(&::SDL_Quit) SDL_Quit = nullptr;
    decltype(&::SDL_SetHint) SDL_SetHint = nullptr;
    decltype(&::SDL_SetWindowTitle) SDL_SetWindowTitle = nullptr;
    decltype(&::SDL_UpdateWindowSurfaceRects) SDL_UpdateWindowSurfaceRects = nullptr;
    /// SDL_BlitSurface is a macro for this one.
    decltype(&::SDL_UpperBlit) SDL_UpperBlit = nullptr;
    decltype(&::SDL_WaitEventTimeout) SDL_WaitEventTimeout = nullptr;
};

/// Loads libSDL2-2.0.so.0 and its functions the first time (thread-safe) and keeps them for the
/// rest of the run. Throws Error naming the library or function that cannot be found; the next
/// call tries again.
const SdlFunctions& sdl_functions();

}  // namespace rt
