#include "rt/core/huge_pages.h"

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rt {

#if defined(__linux__) && defined(MADV_HUGEPAGE)
namespace {
// MADV_COLLAPSE (Linux 6.1), which older C library headers do not name.
#ifdef MADV_COLLAPSE
constexpr int kCollapse = MADV_COLLAPSE;
#else
constexpr int kCollapse = 25;
#endif
}  // namespace
#endif

void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (data == nullptr || bytes < kHugePageWorthwhile) {
        return;
    }
    constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
    constexpr std::uintptr_t kSmallPage = 4096;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t end = begin + bytes;
    // The huge pages inside the room, and also one that sticks out of it by less than a small
    // page at either end: the bytes it adds lie on the room's own first or last small page, so in
    // the same mapping (for a block malloc maps, its 16-byte header; see huge_room).
    const std::uintptr_t below = begin & ~(kHugePage - 1);
    const std::uintptr_t first =
        begin - below < kSmallPage ? below : (begin + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t above = (end + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t last = above - end < kSmallPage ? above : end & ~(kHugePage - 1);
    if (first < last) {
        // A refusal (no transparent huge pages, an old kernel) leaves the memory as it was.
        // NOLINTNEXTLINE(performance-no-int-to-ptr): madvise takes the page-aligned address
        static_cast<void>(madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE));
        if (first < begin && first + kHugePage <= last) {
            // The first huge page holds malloc's header, written before the advice: its small
            // page would keep the other 511 small too. Made a huge page now (Linux 6.1 on), it
            // costs one copy of that page instead of 511 faults.
            // NOLINTNEXTLINE(performance-no-int-to-ptr): as above
            static_cast<void>(madvise(reinterpret_cast<void*>(first), kHugePage, kCollapse));
        }
    }
#else
    static_cast<void>(data);
    static_cast<void>(bytes);
#endif
}

void* allocate_huge(std::size_t bytes) {
    constexpr std::size_t kHugePage = std::size_t{2} << 20;
    if (bytes > std::numeric_limits<std::size_t>::max() - kHugePage) {
        throw std::bad_alloc();
    }
    const std::size_t rounded = (bytes + kHugePage - 1) & ~(kHugePage - 1);
    void* data = std::aligned_alloc(kHugePage, rounded);
    if (data == nullptr) {
        throw std::bad_alloc();
    }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Whole pages on their boundaries: all of the room may become huge pages, however small.
    static_cast<void>(madvise(data, rounded, MADV_HUGEPAGE));
#endif
    return data;
}

void free_huge(void* data) noexcept {
    // NOLINTNEXTLINE(cppcoreguidelines-no-malloc): the pair of allocate_huge's aligned_alloc
    std::free(data);
}

}  // namespace rt
