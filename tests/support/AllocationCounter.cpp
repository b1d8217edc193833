#include "AllocationCounter.h"

#include <atomic>
#include <cstddef>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
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

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t size) {
  if (counting.load())
    ++allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  if (counting.load())
    ++allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  if (counting.load())
    ++allocations;
  return __libc_realloc(p, size);
}
void free(void* p) {
  __libc_free(p);
}
}
