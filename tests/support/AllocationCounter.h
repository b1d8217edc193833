// Counts heap allocations made by a piece of code, for the tests of CONVENTIONS.md's rule that
// code running every force evaluation allocates nothing after its first call at a given size.
//
// How: AllocationCounter.cpp interposes glibc's malloc, calloc and realloc (Eigen allocates with
// malloc and operator new ends there too) and counts the calls made while counting is on. Link
// it into its own test executable only (target pistondyn_test_allocation_counter): it replaces
// the allocator of the whole program. Under AddressSanitizer (PISTONDYN_SANITIZE=address),
// which replaces the allocator itself, it counts the same calls through ASan's allocator hook
// (__sanitizer_install_malloc_and_free_hooks) instead, so the counts are checked there too.
#pragma once

namespace pistondyn::test {

// Resets the count and starts counting.
void startCountingAllocations();
// Stops counting; returns the allocations made since startCountingAllocations().
long stopCountingAllocations();

// Allocations made while f() runs.
template <class F>
long allocationsDuring(F&& f) {
  startCountingAllocations();
  f();
  return stopCountingAllocations();
}

}  // namespace pistondyn::test
