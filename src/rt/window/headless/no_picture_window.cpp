// The window for a build without SDL2 (RT_WITH_WINDOW off): there is never one.
#include "rt/window/picture_window.h"

namespace rt {

bool windows_available() {
    return false;
}

std::unique_ptr<PictureWindow> open_picture_window(const WindowRequest& /*request*/,
                                                   std::string& why_not) {
    why_not = "this rt was built without SDL2 (RT_WITH_WINDOW off)";
    return nullptr;
}

}  // namespace rt
