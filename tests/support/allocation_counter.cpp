// The malloc-family interposers behind support/allocation_counter.hpp.
#include "support/allocation_counter.hpp"

#include <cerrno>
#include <cstddef>
#include <cstdlib>

namespace corrmp::testing {

std::atomic<bool> g_counting_allocations{false};
std::atomic<long> g_allocations{0};

}  // namespace corrmp::testing

#if CORRMP_COUNT_ALLOCATIONS
namespace {
void note_allocation() {
  using corrmp::testing::g_allocations;
  if (corrmp::testing::g_counting_allocations.load(std::memory_order_relaxed)) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
  }
}
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* ptr, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);

void* malloc(std::size_t size) {
  note_allocation();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  note_allocation();
  return __libc_calloc(count, size);
}
void* realloc(void* ptr, std::size_t size) {
  note_allocation();
  return __libc_realloc(ptr, size);
}
void* memalign(std::size_t alignment, std::size_t size) {
  note_allocation();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  note_allocation();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  note_allocation();
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
}
#endif  // CORRMP_COUNT_ALLOCATIONS
