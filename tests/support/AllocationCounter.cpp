#include "AllocationCounter.h"

#include <atomic>
#include <cstddef>

// AddressSanitizer (gcc: __SANITIZE_ADDRESS__, clang: __has_feature) owns malloc and
// free itself, so the __libc_* interposition below cannot be linked with it (malloc would
// be defined twice). There, the same calls are counted through the allocator hook that
// ASan runs on every allocation it serves (malloc, calloc, realloc, operator new, ...).
#if defined(__SANITIZE_ADDRESS__)
#define PISTONDYN_COUNT_THROUGH_ASAN_HOOKS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PISTONDYN_COUNT_THROUGH_ASAN_HOOKS 1
#endif
#endif

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};

void countOne() {
  if (counting.load())
    ++allocations;
}
}  // namespace

namespace pistondyn::test {
void startCountingAllocations() {
  allocations = 0;
  counting = true;
}
long stopCountingAllocations() {
  counting = false;
  return allocations.load();
}
}  // namespace pistondyn::test

#ifdef PISTONDYN_COUNT_THROUGH_ASAN_HOOKS

// sanitizer/allocator_interface.h (clang's; gcc 12 installs no such header, its libasan
// has the function).
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*mallocHook)(const volatile void*,
                                                                            std::size_t),
                                                         void (*freeHook)(const volatile void*));

namespace {
void onMalloc(const volatile void*, std::size_t) {
  countOne();
}
void onFree(const volatile void*) {}
// Installed before main(), so before any test counts.
[[maybe_unused]] const int kHooksInstalled =
    __sanitizer_install_malloc_and_free_hooks(onMalloc, onFree);
}  // namespace

#else

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t size) {
  countOne();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  countOne();
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  countOne();
  return __libc_realloc(p, size);
}
void free(void* p) {
  __libc_free(p);
}
}

#endif
