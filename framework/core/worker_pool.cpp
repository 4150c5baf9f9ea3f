// Worker threads for data-parallel training (worker_pool.hpp).
#include "core/worker_pool.hpp"

#include <stdexcept>

namespace corrmp {

WorkerPool::WorkerPool(int size) : errors_(static_cast<size_t>(size < 1 ? 1 : size)) {
  if (size < 1) throw std::invalid_argument("WorkerPool: size must be >= 1");
  threads_.reserve(static_cast<size_t>(size - 1));
  for (int i = 1; i < size; ++i) threads_.emplace_back([this, i] { worker_loop(i); });
}

WorkerPool::~WorkerPool() {
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
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      call = call_;
      context = context_;
    }
    try {
      call(context, index);
    } catch (...) {
      errors_[static_cast<size_t>(index)] = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--pending_ == 0) done_.notify_one();
    }
  }
}

void WorkerPool::run_erased(void* context, Call call) {
  for (std::exception_ptr& e : errors_) e = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    context_ = context;
    call_ = call;
    pending_ = static_cast<int>(threads_.size());
    ++generation_;
  }
  start_.notify_all();
  try {
    call(context, 0);
  } catch (...) {
    errors_[0] = std::current_exception();
  }
  {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
  }
  for (const std::exception_ptr& e : errors_)
    if (e) std::rethrow_exception(e);
}

}  // namespace corrmp
