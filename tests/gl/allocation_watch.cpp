#include "gl/allocation_watch.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<long> gCount{0};
std::atomic<std::size_t> gLargest{0};

// Every form of new counts and takes its memory from malloc (aligned_alloc for the aligned forms), and every
// form of delete gives it back with free, so that each new meets its own delete: libraries that call the
// nothrow or array forms (Mesa's LLVM) too, as AddressSanitizer's alloc-dealloc-mismatch check requires.
// Out of line, so that GCC does not pair an inlined new with the free and warn (-Wmismatched-new-delete).
[[gnu::noinline]] void* allocate(std::size_t size, std::size_t alignment = 0) noexcept {
    gCount.fetch_add(1, std::memory_order_relaxed);
    std::size_t seen = gLargest.load(std::memory_order_relaxed);
    while (size > seen && !gLargest.compare_exchange_weak(seen, size, std::memory_order_relaxed)) {
    }
    size = size != 0 ? size : 1;
    if (alignment <= alignof(std::max_align_t))
        return std::malloc(size); // NOLINT(cppcoreguidelines-no-malloc)
    return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}
[[gnu::noinline]] void* allocateOrThrow(std::size_t size, std::size_t alignment = 0) {
    if (void* p = allocate(size, alignment)) return p;
    throw std::bad_alloc();
}
[[gnu::noinline]] void release(void* p) noexcept {
    std::free(p); // NOLINT(cppcoreguidelines-no-malloc)
}

} // namespace

namespace shadelab::test {

long allocationCount() {
    return gCount.load();
}
std::size_t largestAllocation() {
    return gLargest.load();
}
void resetLargestAllocation() {
    gLargest = 0;
}

} // namespace shadelab::test

void* operator new(std::size_t size) {
    return allocateOrThrow(size);
}
void* operator new[](std::size_t size) {
    return allocateOrThrow(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    return allocateOrThrow(size, std::size_t(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    return allocateOrThrow(size, std::size_t(alignment));
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocate(size, std::size_t(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocate(size, std::size_t(alignment));
}
void operator delete(void* p) noexcept {
    release(p);
}
void operator delete[](void* p) noexcept {
    release(p);
}
void operator delete(void* p, std::size_t) noexcept {
    release(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    release(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    release(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    release(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    release(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    release(p);
}
