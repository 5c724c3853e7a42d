#pragma once
// Storage for module strings: a std::vector whose resize() leaves new
// elements uninitialised. Every pass sizes its output from upper bounds and
// then overwrites what it uses; zero-filling first would write (and fault in)
// every page twice.
//
// Large buffers are placed on 2 MiB boundaries and offered to the kernel as
// transparent huge pages: a derivation's output is written once, front to
// back, and with 4 KiB pages the kernel's fault per page cost more than the
// rewriting itself for plain D0L systems (millions of one-byte-wide modules).

#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace lsys {

// Allocates `bytes` bytes; from kHugePageBytes up on a huge-page boundary,
// rounded up to whole huge pages and advised as huge pages where the system
// has them. Free with freeBufferBytes and the same `bytes`.
void* allocateBufferBytes(size_t bytes);
void freeBufferBytes(void* pointer, size_t bytes) noexcept;

template <typename T>
struct BufferAllocator : std::allocator<T> {
    using value_type = T;
    template <typename U>
    struct rebind {
        using other = BufferAllocator<U>;
    };

    BufferAllocator() = default;
    template <typename U>
    BufferAllocator(const BufferAllocator<U>&) noexcept {}

    T* allocate(size_t count) {
        if (count > std::allocator_traits<std::allocator<T>>::max_size(*this)) throw std::bad_array_new_length();
        return static_cast<T*>(allocateBufferBytes(count * sizeof(T)));
    }
    void deallocate(T* pointer, size_t count) noexcept { freeBufferBytes(pointer, count * sizeof(T)); }

    template <typename U>
    void construct(U* pointer) noexcept {
        ::new (static_cast<void*>(pointer)) U; // default-initialise: no zeroing
    }
    template <typename U, typename... Args>
    void construct(U* pointer, Args&&... args) {
        ::new (static_cast<void*>(pointer)) U(std::forward<Args>(args)...);
    }
};

template <typename T>
using Buffer = std::vector<T, BufferAllocator<T>>;

} // namespace lsys
