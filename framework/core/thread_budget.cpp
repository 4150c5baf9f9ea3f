// The thread budget and parallel_for (thread_budget.hpp).
#include "core/thread_budget.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <memory>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "core/interrupt.hpp"

namespace corrmp {

namespace {

int hardware_threads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::atomic<int> g_budget{hardware_threads()};

// One loop's shared state: the next index to start, and the first failure.
class Loop {
 public:
  Loop(int count, const std::function<void(int, int)>& task)
      : count_(count), task_(task), errors_(static_cast<size_t>(count)) {}

  // Worker `worker` takes indices until none is left, a task failed or a signal arrived.
  void work(int worker) {
    const InlineLoops inside;
    for (;;) {
      if (interrupt_requested()) {
        interrupted_ = true;
        return;
      }
      const int index = next_.fetch_add(1);
      if (index >= count_ || index > lowest_failure_.load()) return;
      try {
        task_(index, worker);
      } catch (...) {
        errors_[static_cast<size_t>(index)] = std::current_exception();
        int lowest = lowest_failure_.load();
        while (index < lowest && !lowest_failure_.compare_exchange_weak(lowest, index)) {
        }
      }
    }
  }

  // After every worker returned: the lowest index's exception, else Interrupted when tasks were
  // left out because of a signal.
  void rethrow() const {
    for (const std::exception_ptr& error : errors_)
      if (error) std::rethrow_exception(error);
    if (interrupted_) throw Interrupted();
  }

 private:
  const int count_;
  const std::function<void(int, int)>& task_;
  std::vector<std::exception_ptr> errors_;  // one per index, written by its task's thread only
  std::atomic<int> next_{0};
  std::atomic<int> lowest_failure_{std::numeric_limits<int>::max()};
  std::atomic<bool> interrupted_{false};
};

}  // namespace

// True on a thread while it runs a task of a parallel loop, or an InlineLoops lives on it:
// loops started there run inline.
static thread_local bool t_inside_task = false;

InlineLoops::InlineLoops() : saved_(t_inside_task) { t_inside_task = true; }
InlineLoops::~InlineLoops() { t_inside_task = saved_; }

void set_thread_budget(int n) {
  if (n < 1) throw std::invalid_argument("the thread budget must be at least 1");
  g_budget = n;
}

int thread_budget() { return g_budget.load(); }

namespace {
// Waiting threads whose core no one borrowed, less the borrowed cores whose lender stopped
// waiting.
std::atomic<int> g_spare{0};
}  // namespace

SpareThread::SpareThread() { ++g_spare; }
SpareThread::~SpareThread() { --g_spare; }

bool borrow_spare_thread() {
  int spare = g_spare.load();
  while (spare > 0 && !g_spare.compare_exchange_weak(spare, spare - 1)) {
  }
  return spare > 0;
}

void return_spare_thread() { ++g_spare; }

bool spare_thread_recalled() {
  int spare = g_spare.load();
  while (spare < 0 && !g_spare.compare_exchange_weak(spare, spare + 1)) {
  }
  return spare < 0;
}

int parallel_workers(int count) {
  if (count <= 0) return 0;
  return t_inside_task ? 1 : std::min(count, thread_budget());
}

void parallel_for_with_workers(int count, int max_workers,
                               const std::function<void(int, int)>& task) {
  const int workers = std::min(std::max(max_workers, 1), parallel_workers(count));
  if (workers == 0) return;
  if (workers == 1) {
    const InlineLoops inside;
    for (int index = 0; index < count; ++index) {
      check_interrupt();
      task(index, 0);
    }
    return;
  }
  Loop loop(count, task);
  std::vector<std::thread> threads;
  threads.reserve(static_cast<size_t>(workers - 1));
  // A worker with no task left is spare until the loop ends, when they all are.
  std::vector<std::unique_ptr<SpareThread>> spare(static_cast<size_t>(workers));
  for (int worker = 1; worker < workers; ++worker) {
    try {
      threads.emplace_back([&loop, &spare, worker] {
        loop.work(worker);
        spare[static_cast<size_t>(worker)] = std::make_unique<SpareThread>();
      });
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones started share the tasks
    }
  }
  loop.work(0);
  spare[0] = std::make_unique<SpareThread>();
  for (std::thread& thread : threads) thread.join();
  loop.rethrow();
}

void parallel_for(int count, const std::function<void(int)>& task) {
  parallel_for_with_workers(count, std::numeric_limits<int>::max(),
                            [&task](int index, int) { task(index); });
}

}  // namespace corrmp
