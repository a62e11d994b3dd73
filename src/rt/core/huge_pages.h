// Big arrays that rays read at random (acceleration structures' nodes and packets) backed by
// 2 MiB pages where the system allows it: a ray that jumps across a 100 MB structure misses the
// TLB far less often, and the builder takes 512 times fewer page faults writing it. Embree does
// the same for its own arrays.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <new>
#include <vector>

namespace rt {

/// Arrays smaller than this are left alone: they cannot hold a whole aligned 2 MiB page, or
/// would waste much of one.
inline constexpr std::size_t kHugePageWorthwhile = std::size_t{4} << 20;

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes) with huge pages
/// (Linux transparent huge pages, in "madvise" mode on most systems). Only memory not touched yet
/// is affected; nothing happens for small arrays, where the system says no, or elsewhere.
void advise_huge_pages(const void* data, std::size_t bytes);

/// Room of this many bytes or more is allocated in whole huge pages (HugePageAllocator): it fills
/// at least half of the last one.
inline constexpr std::size_t kHugeAllocation = std::size_t{1} << 20;

/// `bytes` rounded up to whole 2 MiB pages, on a 2 MiB boundary, advised as above; freed with
/// free_huge. Throws std::bad_alloc when the system has no such room.
void* allocate_huge(std::size_t bytes);
void free_huge(void* data) noexcept;

/// For the big arrays a build writes once (the BVH's references, nodes and packets): room of
/// kHugeAllocation bytes or more starts on a 2 MiB boundary and fills whole huge pages.
/// std::allocator's big blocks start wherever the system maps them, so advising them left their
/// first and last 2 MiB in small pages, each faulted in on its own (reserve_whole_huge_pages
/// mends that where Linux maps a block of whole huge pages on a boundary), and arrays under 4 MiB
/// were not advised at all. On the virtual machine we measure on, each first touch of a 4 KiB
/// page costs about 10 us. Smaller room comes from std::allocator, and so do
/// the many short-lived arrays of a build's parts (bvh_builder.cpp says why).
template <class T>
class HugePageAllocator {
public:
    using value_type = T;
    HugePageAllocator() = default;
    template <class U>
    explicit(false) HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}

    T* allocate(std::size_t n) {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) {
            throw std::bad_array_new_length();
        }
        if (n * sizeof(T) < kHugeAllocation) {
            return std::allocator<T>().allocate(n);
        }
        return static_cast<T*>(allocate_huge(n * sizeof(T)));
    }
    void deallocate(T* data, std::size_t n) noexcept {
        if (n * sizeof(T) < kHugeAllocation) {
            std::allocator<T>().deallocate(data, n);
        } else {
            free_huge(data);
        }
    }
    friend bool operator==(const HugePageAllocator& /*a*/, const HugePageAllocator& /*b*/) {
        return true;
    }
};

/// How many elements of room to ask std::allocator for, at least n: for big room, as many as
/// fill whole 2 MiB pages together with the 24 bytes glibc's malloc adds to a block (a 16-byte
/// header before it). Such a block is mapped on its own at a whole number of huge pages, which
/// Linux (6.7 on) places on a 2 MiB boundary: the array then starts 16 bytes past one, and
/// advise_huge_pages gives all of it huge pages, where a block of any other size started
/// anywhere and its first and last 2 MiB stayed in small pages (about 500 page faults an array).
/// Elsewhere it asks for less than 2 MiB more room than needed, never touched.
template <class T>
std::size_t huge_room(std::size_t n) {
    constexpr std::size_t kHugePage = std::size_t{2} << 20;
    constexpr std::size_t kMallocBytes = 24;
    if (alignof(T) > __STDCPP_DEFAULT_NEW_ALIGNMENT__ || n * sizeof(T) < kHugePageWorthwhile ||
        n > (std::numeric_limits<std::size_t>::max() / 2) / sizeof(T)) {
        return n;
    }
    const std::size_t whole = (n * sizeof(T) + kMallocBytes + kHugePage - 1) & ~(kHugePage - 1);
    return (whole - kMallocBytes) / sizeof(T);
}

/// v.reserve(n), with the new room advised as above (when v had to grow to hold n).
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
    if (n <= v.capacity()) {
        return;
    }
    v.reserve(n);
    advise_huge_pages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(T));
}

/// reserve_huge with as much room as huge_room says: all of it in huge pages where Linux maps the
/// block on a boundary, for up to 2 MiB more room than asked. For the big arrays of a scene and
/// of a model's mesh, which nothing counts by their capacity (an accelerator's memory is, so
/// theirs stay reserve_huge's).
template <class T>
void reserve_whole_huge_pages(std::vector<T>& v, std::size_t n) {
    if (n > v.capacity()) {
        reserve_huge(v, std::min(huge_room<T>(n), v.max_size()));
    }
}

/// Copies v's elements into advised memory of exactly their size.
template <class T, class A>
void copy_into_huge_pages(std::vector<T, A>& v) {
    std::vector<T, A> copied;
    reserve_huge(copied, v.size());
    copied.assign(v.begin(), v.end());
    v.swap(copied);
}

/// Moves v's elements into advised memory of exactly their size, when they take enough room to
/// be worth it: for arrays filled before anyone knew their size (a scene's, as it is read).
template <class T, class A>
void move_to_huge_pages(std::vector<T, A>& v) {
    if (v.size() * sizeof(T) >= kHugePageWorthwhile) {
        copy_into_huge_pages(v);
    }
}

}  // namespace rt
