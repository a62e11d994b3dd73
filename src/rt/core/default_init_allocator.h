// An allocator whose value-less construction leaves the element uninitialised (default-init), for
// big arrays of plain data that are sized first and then written in parallel: std::vector's
// resize() would otherwise zero every element on one thread, touching all the fresh memory twice.
// Their room comes in whole huge pages (HugePageAllocator), since they are big and written once.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#include "rt/core/huge_pages.h"

namespace rt {

template <class T>
class DefaultInitAllocator : public HugePageAllocator<T> {
public:
    using HugePageAllocator<T>::HugePageAllocator;
    // The allocator requirements name it: the base's would rebind to the base.
    template <class U>
    struct rebind {  // NOLINT(readability-identifier-naming)
        using other = DefaultInitAllocator<U>;
    };

    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::construct_at(p, std::forward<Args>(args)...);
    }
};

/// For plain data whose default member initialisers would still write every element (a box's
/// empty +-inf): value-less construction writes nothing at all, so that an array sized first can
/// be written by several threads, each faulting in its own part of the fresh memory. Only for
/// trivially copyable and destructible types, whose objects the allocation itself creates (C++20's
/// implicit-lifetime rule); every element must be assigned before it is read.
template <class T>
class UnwrittenAllocator : public HugePageAllocator<T> {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "only plain data may be left unwritten");

public:
    using HugePageAllocator<T>::HugePageAllocator;
    template <class U>
    struct rebind {  // NOLINT(readability-identifier-naming)
        using other = UnwrittenAllocator<U>;
    };

    template <class U>
    void construct(U* /*p*/) noexcept {}
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::construct_at(p, std::forward<Args>(args)...);
    }
};

}  // namespace rt
