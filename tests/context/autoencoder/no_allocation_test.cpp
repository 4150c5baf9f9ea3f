// Checks that a data-parallel autoencoder training step (context/autoencoder/
// data_parallel_trainer.hpp), once every worker has seen its largest shard, performs no heap
// allocation on any thread: the worker pool, the replicas' activation buffers, the gradient
// reduction and Adam all reuse their memory. A tiny architecture keeps Eigen's matrix products
// within its stack blocking limit (the paper's 32x32 layers exceed it, nn/conv2d.hpp).
//
// Allocations are counted by tests/support/allocation_counter.hpp.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <numeric>
#include <utility>
#include <vector>

#include "context/autoencoder/data_parallel_trainer.hpp"

#include "support/allocation_counter.hpp"

namespace corrmp {
namespace {

TEST(AutoencoderNoAllocation, CounterSeesAllocationsOnWorkerThreads) {
  if (!testing::kAllocationCounting) GTEST_SKIP() << "allocation counting is off under sanitizers";
  WorkerPool pool(2);
  testing::g_allocations = 0;
  testing::g_counting_allocations = true;
  pool.run([](int) {
    Eigen::VectorXf* volatile v = new Eigen::VectorXf(100);
    delete v;
  });
  testing::g_counting_allocations = false;
  EXPECT_GE(testing::g_allocations.load(),
            4);  // operator new and Eigen's aligned malloc, per worker
}

// Data-parallel steps of an autoencoder of 8x8 images with these strides and filters allocate
// nothing once warmed up.
void expect_no_allocation_after_warm_up(std::vector<int> strides, std::vector<int> filters) {
  AutoencoderArchitecture a;
  a.image_size = 8;
  a.strides = std::move(strides);
  a.filters = std::move(filters);
  a.latent_size = 3;
  nn::Rng init(1);
  ConvAutoencoder<float> model(a, init);
  nn::Mat<float> data = nn::Mat<float>::Random(12, model.image_values()).cwiseAbs();
  std::vector<int> order(12);
  std::iota(order.begin(), order.end(), 0);
  DataParallelTrainer trainer(model, 2, 1e-3);
  trainer.step(data, order.data(), 12);  // warm-up with the largest minibatch

  testing::g_allocations = 0;
  testing::g_counting_allocations = true;
  for (int i = 0; i < 5; ++i) {
    trainer.step(data, order.data(), 12);
    trainer.step(data, order.data() + 3, 7);  // a smaller last minibatch
  }
  testing::g_counting_allocations = false;
  EXPECT_EQ(testing::g_allocations.load(), 0);
}

TEST(AutoencoderNoAllocation, DataParallelStepAfterWarmUp) {
  if (!testing::kAllocationCounting) GTEST_SKIP() << "allocation counting is off under sanitizers";
  expect_no_allocation_after_warm_up({2, 1}, {4, 4});
}

// With 16 channels the stride-2 layers run nn/winograd_stride2_conv3x3.hpp.
TEST(AutoencoderNoAllocation, DataParallelStepAfterWarmUpWithStride2Winograd) {
  if (!testing::kAllocationCounting) GTEST_SKIP() << "allocation counting is off under sanitizers";
  expect_no_allocation_after_warm_up({2, 2}, {16, 16});
}

}  // namespace
}  // namespace corrmp
