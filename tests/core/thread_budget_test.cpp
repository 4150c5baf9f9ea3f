// Tests of core/thread_budget.hpp: the budget, and parallel_for running every task once on at
// most the budget's threads, inline when it is 1 or when nested, with deterministic errors.
#include "core/thread_budget.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/interrupt.hpp"

namespace corrmp {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;

// Restores the default budget after each test.
class ThreadBudget : public ::testing::Test {
 protected:
  void SetUp() override { saved_ = thread_budget(); }
  void TearDown() override { set_thread_budget(saved_); }

 private:
  int saved_ = 1;
};

TEST_F(ThreadBudget, DefaultsToTheHardwareThreadsAndRejectsLessThanOne) {
  EXPECT_EQ(thread_budget(), std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  set_thread_budget(3);
  EXPECT_EQ(thread_budget(), 3);
  EXPECT_THROW(set_thread_budget(0), std::invalid_argument);
  EXPECT_EQ(thread_budget(), 3);
  EXPECT_EQ(parallel_workers(10), 3);
  EXPECT_EQ(parallel_workers(2), 2);
  EXPECT_EQ(parallel_workers(0), 0);
}

TEST_F(ThreadBudget, RunsEveryIndexOnceForEveryBudget) {
  for (int budget : {1, 2, 4}) {
    set_thread_budget(budget);
    for (int count : {0, 1, 7, 100}) {
      std::vector<std::atomic<int>> calls(static_cast<size_t>(count));
      parallel_for(count, [&](int i) { ++calls[static_cast<size_t>(i)]; });
      for (int i = 0; i < count; ++i) {
        ASSERT_EQ(calls[static_cast<size_t>(i)].load(), 1)
            << "index " << i << ", budget " << budget << ", count " << count;
      }
    }
  }
}

TEST_F(ThreadBudget, NeverRunsMoreTasksAtOnceThanTheBudget) {
  set_thread_budget(3);
  std::atomic<int> running{0}, most{0};
  std::mutex mutex;
  std::set<std::thread::id> threads;
  parallel_for(30, [&](int) {
    const int now = ++running;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      threads.insert(std::this_thread::get_id());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    --running;
  });
  EXPECT_LE(most.load(), 3);
  EXPECT_LE(threads.size(), 3u);
  EXPECT_TRUE(threads.count(std::this_thread::get_id()) == 1) << "the caller works too";
}

TEST_F(ThreadBudget, ABudgetOfOneRunsInlineInIndexOrder) {
  set_thread_budget(1);
  std::vector<int> order;
  parallel_for(5, [&](int i) { order.push_back(i); });
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
  const auto caller = std::this_thread::get_id();
  parallel_for(3, [&](int) { EXPECT_EQ(std::this_thread::get_id(), caller); });
}

TEST_F(ThreadBudget, NestedLoopsRunInlineOnTheTasksThread) {
  set_thread_budget(2);
  std::atomic<int> inner_calls{0};
  parallel_for(4, [&](int) {
    EXPECT_EQ(parallel_workers(8), 1);
    const auto outer = std::this_thread::get_id();
    parallel_for(8, [&](int) {
      EXPECT_EQ(std::this_thread::get_id(), outer);
      ++inner_calls;
    });
  });
  EXPECT_EQ(inner_calls.load(), 32);
  EXPECT_EQ(parallel_workers(8), 2) << "outside a task the budget applies again";
}

TEST_F(ThreadBudget, RethrowsTheLowestIndexAfterTheStartedTasksFinished) {
  for (int budget : {1, 2, 4}) {
    set_thread_budget(budget);
    std::vector<std::atomic<int>> started(40), finished(40);
    EXPECT_THAT(
        [&] {
          parallel_for(40, [&](int i) {
            started[static_cast<size_t>(i)] = 1;
            std::this_thread::sleep_for(std::chrono::microseconds(200 * (i % 3)));
            finished[static_cast<size_t>(i)] = 1;
            if (i == 9 || i == 13) throw std::runtime_error("task " + std::to_string(i));
          });
        },
        ThrowsMessage<std::runtime_error>(StrEq("task 9")))
        << "budget " << budget;
    // Every task before the failure ran, and every task started had finished by the time the
    // exception arrived.
    for (int i = 0; i <= 9; ++i) EXPECT_EQ(finished[static_cast<size_t>(i)].load(), 1);
    for (int i = 0; i < 40; ++i) {
      EXPECT_EQ(started[static_cast<size_t>(i)].load(), finished[static_cast<size_t>(i)].load())
          << "task " << i << ", budget " << budget;
    }
    if (budget == 1) {
      for (int i = 10; i < 40; ++i) EXPECT_EQ(started[static_cast<size_t>(i)].load(), 0);
    }
  }
}

TEST_F(ThreadBudget, WorkersRunOneTaskAtATimeAndStayBelowTheLimit) {
  set_thread_budget(4);
  std::vector<std::atomic<int>> busy(4);
  std::atomic<int> clashes{0}, out_of_range{0}, calls{0};
  parallel_for_with_workers(50, 2, [&](int, int worker) {
    if (worker < 0 || worker >= 2) {
      ++out_of_range;
      return;
    }
    if (busy[static_cast<size_t>(worker)]++ != 0) ++clashes;
    std::this_thread::sleep_for(std::chrono::microseconds(300));
    --busy[static_cast<size_t>(worker)];
    ++calls;
  });
  EXPECT_EQ(out_of_range.load(), 0);
  EXPECT_EQ(clashes.load(), 0);
  EXPECT_EQ(calls.load(), 50);
}

// A signal stops further tasks from starting and gives Interrupted. The handler's flag cannot be
// cleared, so this runs in a child process.
TEST_F(ThreadBudget, ASignalStopsTheLoopWithInterrupted) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        install_interrupt_handlers();
        set_thread_budget(2);
        std::atomic<int> calls{0};
        try {
          parallel_for(1000, [&](int i) {
            ++calls;
            if (i == 5) std::raise(SIGINT);
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          });
        } catch (const Interrupted&) {
          std::exit(calls.load() < 1000 ? 0 : 2);
        }
        std::exit(1);
      },
      ::testing::ExitedWithCode(0), "");
}

// A waiting thread's core is lent once at a time, and given back.
TEST_F(ThreadBudget, AWaitingThreadsCoreIsLentToOneBorrowerAtATime) {
  EXPECT_FALSE(borrow_spare_thread());
  {
    const SpareThread waiting;
    EXPECT_TRUE(borrow_spare_thread());
    EXPECT_FALSE(borrow_spare_thread());
    return_spare_thread();
    EXPECT_TRUE(borrow_spare_thread());
    return_spare_thread();
  }
  EXPECT_FALSE(borrow_spare_thread());
  // A lender that stops waiting recalls its core from the borrower, once.
  {
    const SpareThread waiting;
    EXPECT_TRUE(borrow_spare_thread());
    EXPECT_FALSE(spare_thread_recalled());
  }
  EXPECT_TRUE(spare_thread_recalled());
  EXPECT_FALSE(spare_thread_recalled());
  EXPECT_FALSE(borrow_spare_thread());
}

// A loop's worker that found no task left lends its core to the tasks still running, until the
// loop ends.
TEST_F(ThreadBudget, ALoopsIdleWorkerLendsItsCoreUntilTheLoopEnds) {
  set_thread_budget(2);
  std::atomic<bool> borrowed{false};
  parallel_for(2, [&](int index) {
    if (index == 0) return;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!borrowed && std::chrono::steady_clock::now() < give_up) {
      if (borrow_spare_thread()) {
        borrowed = true;
        return_spare_thread();
      }
      std::this_thread::yield();
    }
  });
  EXPECT_TRUE(borrowed);
  EXPECT_FALSE(borrow_spare_thread());
}

}  // namespace
}  // namespace corrmp
