// A fixed set of worker threads for steps repeated many times, such as the minibatches of the
// data-parallel autoencoder training (context/autoencoder/data_parallel_trainer.hpp, paper
// Section III "Learning the Context"), without creating threads per step. For a few long
// independent tasks, parallel_for (core/thread_budget.hpp) is simpler.
//
// run(task) calls task(i) once for each i in [0, size()): i = 0 on the calling thread, the
// others on the pool's threads, and returns when all calls have finished. Which thread runs
// which index is fixed, so per-index work is deterministic. An exception thrown by a task is
// rethrown by run() (the one of the lowest index) after all tasks have finished. run() does not
// allocate; it must not be called from two threads at once, nor from inside a task. Between
// runs the workers, and run() while it waits for them, poll for tens of microseconds before
// they sleep, so a loop of short steps (a CNMP update, cnmp/parallel_cnmp_step.hpp) does not
// pay for waking a thread each time.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace corrmp {

class WorkerPool {
 public:
  /// A pool of `size` workers (size - 1 threads besides the caller); size >= 1.
  explicit WorkerPool(int size);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int size() const { return static_cast<int>(threads_.size()) + 1; }

  /// Runs task(0), ..., task(size() - 1) in parallel and waits for all of them.
  template <class Task>
  void run(Task&& task) {
    using T = std::remove_reference_t<Task>;
    run_erased(static_cast<void*>(&task),
               [](void* context, int index) { (*static_cast<T*>(context))(index); });
  }

 private:
  using Call = void (*)(void*, int);
  void run_erased(void* context, Call call);
  void worker_loop(int index);
  // Tells the workers to stop and joins them.
  void stop();

  std::vector<std::thread> threads_;
  std::vector<std::exception_ptr> errors_;  // one per index
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  std::atomic<std::uint64_t> generation_{0};  // written under mutex_, polled without it
  std::atomic<int> pending_{0};
  bool stopping_ = false;
  void* context_ = nullptr;
  Call call_ = nullptr;
};

}  // namespace corrmp
