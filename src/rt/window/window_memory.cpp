#include <algorithm>

#include "rt/window/picture_window.h"

#include <fmt/format.h>

namespace rt {

std::string window_memory_refusal(int width, int height, const std::optional<MemoryLimit>& limit) {
    const std::uint64_t needed = static_cast<std::uint64_t>(std::max(width, 0)) *
                                 static_cast<std::uint64_t>(std::max(height, 0)) *
                                 kWindowBytesPerViewPixel;
    if (!limit || needed <= limit->bytes) {
        return "";
    }
    return fmt::format(
        "no window: one of {} x {} pixels needs about {}, more than the {} available ({})", width,
        height, format_bytes(needed), format_bytes(limit->bytes), limit->source);
}

}  // namespace rt
