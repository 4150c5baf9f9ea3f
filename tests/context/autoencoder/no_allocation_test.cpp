// Checks that a data-parallel autoencoder training step (context/autoencoder/
// data_parallel_trainer.hpp), once every worker has seen its largest shard, performs no heap
// allocation on any thread: the worker pool, the replicas' activation buffers, the gradient
// reduction and Adam all reuse their memory. A tiny architecture keeps Eigen's matrix products
// within its stack blocking limit (the paper's 32x32 layers exceed it, nn/conv2d.hpp).
//
// Like tests/nn/no_allocation_test.cpp, the binary interposes the malloc family (forwarding to
// glibc's __libc_* functions) and counts calls while a flag is set; under sanitizers, which
// bring their own allocator, the interposers are left out and the test is skipped.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <numeric>

#include "context/autoencoder/data_parallel_trainer.hpp"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CORRMP_AE_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define CORRMP_AE_COUNT_ALLOCATIONS 0
#endif
#endif
#ifndef CORRMP_AE_COUNT_ALLOCATIONS
#define CORRMP_AE_COUNT_ALLOCATIONS 1
#endif

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

[[maybe_unused]] void note_allocation() {
  if (g_counting.load(std::memory_order_relaxed))
    g_allocations.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

#if CORRMP_AE_COUNT_ALLOCATIONS
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
#endif  // CORRMP_AE_COUNT_ALLOCATIONS

namespace corrmp {
namespace {

TEST(AutoencoderNoAllocation, CounterSeesAllocationsOnWorkerThreads) {
  if (!CORRMP_AE_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under sanitizers";
  WorkerPool pool(2);
  g_allocations = 0;
  g_counting = true;
  pool.run([](int) {
    Eigen::VectorXf* volatile v = new Eigen::VectorXf(100);
    delete v;
  });
  g_counting = false;
  EXPECT_GE(g_allocations.load(), 4);  // operator new and Eigen's aligned malloc, per worker
}

TEST(AutoencoderNoAllocation, DataParallelStepAfterWarmUp) {
  if (!CORRMP_AE_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under sanitizers";
  AutoencoderArchitecture a;
  a.image_size = 8;
  a.strides = {2, 1};
  a.filters = {4, 4};
  a.latent_size = 3;
  nn::Rng init(1);
  ConvAutoencoder<float> model(a, init);
  nn::Mat<float> data = nn::Mat<float>::Random(12, model.image_values()).cwiseAbs();
  std::vector<int> order(12);
  std::iota(order.begin(), order.end(), 0);
  DataParallelTrainer trainer(model, 2, 1e-3);
  trainer.step(data, order.data(), 12);  // warm-up with the largest minibatch

  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < 5; ++i) {
    trainer.step(data, order.data(), 12);
    trainer.step(data, order.data() + 3, 7);  // a smaller last minibatch
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
}

}  // namespace
}  // namespace corrmp
