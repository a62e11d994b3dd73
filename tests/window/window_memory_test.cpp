// The window's memory check: a view too large for the memory left is refused with the figures,
// before the window's picture is allocated.
#include <optional>
#include <string>

#include "rt/window/picture_window.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;

TEST(WindowMemory, AViewTooLargeForTheMemoryLeftIsRefusedWithTheFigures) {
    // 16000 x 16000 pixels at 32 bytes: 8,192,000,000 bytes, 7.6 GiB.
    const MemoryLimit four{4 * kGiB, "the address-space limit (ulimit -v)"};
    EXPECT_EQ(window_memory_refusal(16000, 16000, four),
              "no window: one of 16000 x 16000 pixels needs about 7.6 GiB, more than the 4.0 GiB "
              "available (the address-space limit (ulimit -v))");
    EXPECT_EQ(window_memory_refusal(16000, 16000, MemoryLimit{8 * kGiB, "x"}), "");
    EXPECT_EQ(window_memory_refusal(512, 400, four), "");
}

TEST(WindowMemory, WithoutAKnownLimitAnySizeOpens) {
    EXPECT_EQ(window_memory_refusal(16384, 16384, std::nullopt), "");
}

TEST(WindowMemory, CountsTheBytesAPixelMeasured) {
    // Exactly at the limit it fits; one byte short it does not.
    const std::uint64_t needed = 1000ULL * 1000ULL * kWindowBytesPerViewPixel;
    EXPECT_EQ(window_memory_refusal(1000, 1000, MemoryLimit{needed, "x"}), "");
    EXPECT_NE(window_memory_refusal(1000, 1000, MemoryLimit{needed - 1, "x"}), "");
}

}  // namespace
}  // namespace rt
