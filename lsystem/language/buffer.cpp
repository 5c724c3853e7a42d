#include "lsystem/language/buffer.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace lsys {
namespace {

constexpr size_t kHugePageBytes = size_t{2} << 20;

size_t roundedToHugePages(size_t bytes) { return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes; }

} // namespace

void* allocateBufferBytes(size_t bytes) {
    if (bytes < kHugePageBytes) return ::operator new(bytes);
    const size_t rounded = roundedToHugePages(bytes);
    void* pointer = ::operator new (rounded, std::align_val_t{kHugePageBytes});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: where the kernel has no huge pages to give (or none at
    // all) the buffer is the same, in small pages.
    madvise(pointer, rounded, MADV_HUGEPAGE);
#endif
    return pointer;
}

// The unsized deletes: clang (tools/fuzz.sh's) declares the sized ones only
// with -fsized-deallocation.
void freeBufferBytes(void* pointer, size_t bytes) noexcept {
    if (bytes < kHugePageBytes)
        ::operator delete(pointer);
    else
        ::operator delete (pointer, std::align_val_t{kHugePageBytes});
}

} // namespace lsys
