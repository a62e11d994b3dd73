#include "rt/window/sdl/sdl_functions.h"

#include "rt/core/shared_library.h"

namespace rt {

namespace {

SdlFunctions find_functions(const SharedLibrary& library) {
    SdlFunctions f;
// The member and the symbol have the function's name; the type comes from SDL's declaration.
#define RT_FIND(name) f.name = library.function<decltype(::name)>(#name)
    RT_FIND(SDL_CreateRGBSurfaceWithFormatFrom);
    RT_FIND(SDL_CreateWindow);
    RT_FIND(SDL_DestroyWindow);
    RT_FIND(SDL_FreeSurface);
    RT_FIND(SDL_GetCurrentVideoDriver);
    RT_FIND(SDL_GetError);
    RT_FIND(SDL_GetTicks);
    RT_FIND(SDL_GetWindowSurface);
    RT_FIND(SDL_HideWindow);
    RT_FIND(SDL_Init);
    RT_FIND(SDL_PollEvent);
    RT_FIND(SDL_Quit);
    RT_FIND(SDL_SetHint);
    RT_FIND(SDL_SetWindowTitle);
    RT_FIND(SDL_UpdateWindowSurfaceRects);
    RT_FIND(SDL_UpperBlit);
    RT_FIND(SDL_WaitEventTimeout);
#undef RT_FIND
    return f;
}

}  // namespace

const SdlFunctions& sdl_functions() {
    // Never closed: SDL may leave threads and handlers behind after SDL_Quit, and unloading its
    // code under them at exit would gain nothing.
    static const SharedLibrary* const library = new SharedLibrary("libSDL2-2.0.so.0");
    static const SdlFunctions functions = find_functions(*library);
    return functions;
}

}  // namespace rt
