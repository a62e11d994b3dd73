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

/// What an allocator's value-less construction (std::vector's resize) does with an element.
enum class BlankElement {
    /// Default-initialised: left as it is for a type without default member initialisers.
    DefaultInit,
    /// Not written at all, even where default member initialisers would write (a box's empty
    /// +-inf), so that an array sized first can be written by several threads, each faulting in
    /// its own part of the fresh memory. Only for trivially copyable and destructible types,
    /// whose objects the allocation itself creates (C++20's implicit-lifetime rule); every
    /// element must be assigned before it is read.
    Unwritten,
};

template <class T, BlankElement kBlank>
class BlankAllocator : public HugePageAllocator<T> {
    static_assert(kBlank != BlankElement::Unwritten ||
                      (std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>),
                  "only plain data may be left unwritten");

public:
    using HugePageAllocator<T>::HugePageAllocator;
    // The allocator requirements name it: the base's would rebind to the base.
    template <class U>
    struct rebind {  // NOLINT(readability-identifier-naming)
        using other = BlankAllocator<U, kBlank>;
    };

    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        if constexpr (kBlank == BlankElement::DefaultInit) {
            ::new (static_cast<void*>(p)) U;
        }
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::construct_at(p, std::forward<Args>(args)...);
    }
};

template <class T>
using DefaultInitAllocator = BlankAllocator<T, BlankElement::DefaultInit>;
template <class T>
using UnwrittenAllocator = BlankAllocator<T, BlankElement::Unwritten>;

}  // namespace rt
