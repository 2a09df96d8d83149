// SPDX-License-Identifier: MIT
#pragma once
// An allocator for large arrays read in random order (BVH nodes, a mesh's leaf triangles). On
// Linux, an array of 2 MiB or more is aligned to 2 MiB and marked for transparent huge pages
// (madvise), so a ray's walk over tens of megabytes misses the TLB far less: more incoherent
// rays per second on a large mesh (bench/README.md). Elsewhere, and for smaller
// arrays, it is std::allocator.

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace photon {

template <class T> class HugePageAllocator {
public:
    using value_type = T;
    static constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;

    HugePageAllocator() noexcept = default;
    template <class U> HugePageAllocator(const HugePageAllocator<U>&) noexcept {}  // NOLINT: rebinding

    [[nodiscard]] T* allocate(std::size_t n) {
#if defined(__linux__)
        if (is_huge(n)) {
            void* p = std::aligned_alloc(huge_page_bytes, rounded(n));
            if (p == nullptr) throw std::bad_alloc();
            ::madvise(p, rounded(n), MADV_HUGEPAGE);  // advice: if refused, small pages serve
            return static_cast<T*>(p);
        }
#endif
        return std::allocator<T>{}.allocate(n);
    }
    void deallocate(T* p, std::size_t n) noexcept {
#if defined(__linux__)
        if (is_huge(n)) {
            std::free(p);
            return;
        }
#endif
        std::allocator<T>{}.deallocate(p, n);
    }

    template <class U> friend bool operator==(const HugePageAllocator&, const HugePageAllocator<U>&) noexcept {
        return true;
    }

private:
    static bool is_huge(std::size_t n) noexcept { return n >= huge_page_bytes / sizeof(T); }
    static std::size_t rounded(std::size_t n) noexcept {
        return (n * sizeof(T) + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
    }
};

}  // namespace photon
