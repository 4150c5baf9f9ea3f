// Worker threads for data-parallel training (worker_pool.hpp).
#include "core/worker_pool.hpp"

#include <stdexcept>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace corrmp {

namespace {

// Polls `done` for 4096 pauses (tens of microseconds) before the caller sleeps: the steps of
// a training loop follow one another within microseconds, much faster than a sleeping thread
// wakes up, while a thread that finds nothing to do soon sleeps and leaves its core.
template <class Done>
bool spin_until(Done&& done) {
  for (int spins = 0; spins < (1 << 12); ++spins) {
    if (done()) return true;
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
  }
  return done();
}

}  // namespace

WorkerPool::WorkerPool(int size) : errors_(static_cast<size_t>(size < 1 ? 1 : size)) {
  if (size < 1) throw std::invalid_argument("WorkerPool: size must be >= 1");
  threads_.reserve(static_cast<size_t>(size - 1));
  try {
    for (int i = 1; i < size; ++i) threads_.emplace_back([this, i] { worker_loop(i); });
  } catch (...) {
    stop();  // the threads started (a std::system_error: no more threads to be had)
    throw;
  }
}

WorkerPool::~WorkerPool() { stop(); }

void WorkerPool::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void WorkerPool::worker_loop(int index) {
  std::uint64_t seen = 0;
  for (;;) {
    Call call = nullptr;
    void* context = nullptr;
    const auto started = [&] { return generation_.load(std::memory_order_acquire) != seen; };
    if (!spin_until(started)) {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || started(); });
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) return;
      seen = generation_.load(std::memory_order_relaxed);
      call = call_;
      context = context_;
    }
    try {
      call(context, index);
    } catch (...) {
      errors_[static_cast<size_t>(index)] = std::current_exception();
    }
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      std::lock_guard<std::mutex> lock(mutex_);  // so that run() cannot miss the notification
      done_.notify_one();
    }
  }
}

void WorkerPool::run_erased(void* context, Call call) {
  for (std::exception_ptr& e : errors_) e = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    context_ = context;
    call_ = call;
    pending_.store(static_cast<int>(threads_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  start_.notify_all();
  try {
    call(context, 0);
  } catch (...) {
    errors_[0] = std::current_exception();
  }
  const auto finished = [&] { return pending_.load(std::memory_order_acquire) == 0; };
  if (!spin_until(finished)) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, finished);
  }
  for (const std::exception_ptr& e : errors_)
    if (e) std::rethrow_exception(e);
}

}  // namespace corrmp
