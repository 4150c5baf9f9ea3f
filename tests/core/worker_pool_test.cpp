// Tests of core/worker_pool.hpp: every index runs once per run(), exceptions are rethrown and
// the pool stays usable.
#include "core/worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>

namespace corrmp {
namespace {

TEST(WorkerPool, RunsEveryIndexOnceAndRethrows) {
  WorkerPool pool(3);
  ASSERT_EQ(pool.size(), 3);
  for (int round = 0; round < 50; ++round) {
    std::atomic<int> calls[3] = {0, 0, 0};
    pool.run([&](int i) { ++calls[i]; });
    for (auto& c : calls) ASSERT_EQ(c.load(), 1);
  }
  EXPECT_THROW(pool.run([](int i) {
    if (i == 2) throw std::runtime_error("worker 2 failed");
  }),
               std::runtime_error);
  std::atomic<int> after{0};
  pool.run([&](int) { ++after; });  // still usable after an exception
  EXPECT_EQ(after.load(), 3);
  EXPECT_THROW(WorkerPool(0), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
