// Counting heap allocations in tests of the no-allocation property of training
// steps. A test binary that links support/allocation_counter.cpp interposes the
// malloc family (forwarding to glibc's __libc_* functions) and counts calls
// while counting is on, on every thread; this catches operator new and Eigen's
// aligned_malloc alike. Sanitizers bring their own allocator, so under them
// nothing is interposed and kAllocationCounting is false (tests skip).
#pragma once

#include <atomic>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CORRMP_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define CORRMP_COUNT_ALLOCATIONS 0
#endif
#endif
#ifndef CORRMP_COUNT_ALLOCATIONS
#define CORRMP_COUNT_ALLOCATIONS 1
#endif

namespace corrmp::testing {

constexpr bool kAllocationCounting = CORRMP_COUNT_ALLOCATIONS != 0;

extern std::atomic<bool> g_counting_allocations;
extern std::atomic<long> g_allocations;

// Counts heap allocations made while `body` runs.
template <class F>
long count_allocations(F&& body) {
  g_allocations = 0;
  g_counting_allocations = true;
  body();
  g_counting_allocations = false;
  return g_allocations.load();
}

}  // namespace corrmp::testing
