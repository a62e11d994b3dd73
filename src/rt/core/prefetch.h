// Asking the cache for a line before it is read, in a form the compiler must keep.
//
// GCC treats __builtin_prefetch as free of side effects. A function that does nothing but
// prefetch is then found "const" by its interprocedural analysis, and every call to it that is
// not inlined first is deleted as dead code, without a warning. That silently removed the
// prefetches of the BVH's single-ray walk and of its leaf filling. An inline asm statement marked
// volatile has a side effect the compiler must respect, so the instruction stays where the code
// puts it.
#pragma once

namespace rt {

/// Asks for the cache line holding `address` into every level of the cache. Never faults: the
/// address may lie past the end of an array.
inline void prefetch(const void* address) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    asm volatile("prefetcht0 (%0)" : : "r"(address));
#elif defined(__GNUC__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

}  // namespace rt
