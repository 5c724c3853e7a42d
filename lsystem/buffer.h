#pragma once
// Storage for module strings: a std::vector whose resize() leaves new
// elements uninitialised. Every pass sizes its output from upper bounds and
// then overwrites what it uses; zero-filling first would write (and fault in)
// every page twice.

#include <memory>
#include <utility>
#include <vector>

namespace lsys {

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
