// Big arrays that rays read at random (acceleration structures' nodes and packets) backed by
// 2 MiB pages where the system allows it: a ray that jumps across a 100 MB structure misses the
// TLB far less often, and the builder takes 512 times fewer page faults writing it. Embree does
// the same for its own arrays.
#pragma once

#include <cstddef>
#include <vector>

namespace rt {

/// Arrays smaller than this are left alone: they cannot hold a whole aligned 2 MiB page, or
/// would waste much of one.
inline constexpr std::size_t kHugePageWorthwhile = std::size_t{4} << 20;

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes) with huge pages
/// (Linux transparent huge pages, in "madvise" mode on most systems). Only memory not touched yet
/// is affected; nothing happens for small arrays, where the system says no, or elsewhere.
void advise_huge_pages(const void* data, std::size_t bytes);

/// v.reserve(n), with the new room advised as above (when v had to grow to hold n).
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
    if (n <= v.capacity()) {
        return;
    }
    v.reserve(n);
    advise_huge_pages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(T));
}

/// Copies v's elements into advised memory of exactly their size.
template <class T, class A>
void copy_into_huge_pages(std::vector<T, A>& v) {
    std::vector<T, A> copied;
    reserve_huge(copied, v.size());
    copied.assign(v.begin(), v.end());
    v.swap(copied);
}

/// v.shrink_to_fit(), into advised memory: a plain shrink_to_fit copies into memory that gets
/// small pages.
template <class T, class A>
void shrink_to_fit_huge(std::vector<T, A>& v) {
    if (v.capacity() != v.size()) {
        copy_into_huge_pages(v);
    }
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
