#include "allocationcount.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<qint64> g_allocations{0};

void *counted(std::size_t size) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
} // namespace

namespace tipscope::bench {
qint64 allocationsSoFar() {
    return g_allocations.load(std::memory_order_relaxed);
}
} // namespace tipscope::bench

// The sanitizers bring their own operator new, which must stay theirs (gcc says so by a macro,
// clang by a feature).
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define TIPSCOPE_SANITIZED_NEW
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TIPSCOPE_SANITIZED_NEW
#endif
#ifndef TIPSCOPE_SANITIZED_NEW
void *operator new(std::size_t size) {
    return counted(size);
}
void *operator new[](std::size_t size) {
    return counted(size);
}
void *operator new(std::size_t size, const std::nothrow_t &) noexcept {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size ? size : 1);
}
void *operator new[](std::size_t size, const std::nothrow_t &) noexcept {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size ? size : 1);
}
void operator delete(void *p) noexcept {
    std::free(p);
}
void operator delete[](void *p) noexcept {
    std::free(p);
}
void operator delete(void *p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void *p, std::size_t) noexcept {
    std::free(p);
}
#endif
