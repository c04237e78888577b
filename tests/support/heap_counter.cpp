#include "tests/support/heap_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<long> g_allocations{0};
std::atomic<long> g_deallocations{0};

void* counted_malloc(std::size_t size) {
    ++g_allocations;
    return std::malloc(size ? size : 1);
}

void* counted_aligned(std::size_t size, std::align_val_t align) {
    ++g_allocations;
    const std::size_t a = static_cast<std::size_t>(align);
    return std::aligned_alloc(a, (size + a - 1) / a * a);
}

// Out of line, so the compiler does not pair std::free with a new in view.
__attribute__((noinline)) void counted_free(void* p) {
    if (p) ++g_deallocations;
    std::free(p);
}

void* or_throw(void* p) {
    if (!p) throw std::bad_alloc();
    return p;
}

}  // namespace

namespace test_support {

heap_counter::heap_counter()
    : m_allocations_at_start(g_allocations.load()),
      m_deallocations_at_start(g_deallocations.load()) {}

long heap_counter::allocations() const { return g_allocations.load() - m_allocations_at_start; }

long heap_counter::deallocations() const {
    return g_deallocations.load() - m_deallocations_at_start;
}

}  // namespace test_support

void* operator new(std::size_t size) { return or_throw(counted_malloc(size)); }
void* operator new[](std::size_t size) { return or_throw(counted_malloc(size)); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return counted_malloc(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return counted_malloc(size);
}
void* operator new(std::size_t size, std::align_val_t a) {
    return or_throw(counted_aligned(size, a));
}
void* operator new[](std::size_t size, std::align_val_t a) {
    return or_throw(counted_aligned(size, a));
}
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { counted_free(p); }
