// A team of threads computing one training step together (the CNMP update of
// cnmp/parallel_cnmp_step.hpp, paper Section III-A): every member runs the same code, computes
// its share of each layer (share() cuts a range into one contiguous part per member) and waits
// for the others at sync() before the next layer reads what they wrote. A team of one never
// waits. The barrier spins, then yields: a step has a dozen of them, each far shorter than a
// sleep and a wake-up of the operating system would take.
#pragma once

#include <atomic>
#include <stdexcept>
#include <thread>
#include <utility>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include "nn/tensor.hpp"

namespace corrmp::nn {

/// Thrown by SpinBarrier::wait once a member has aborted the team.
struct TeamAborted : std::runtime_error {
  TeamAborted() : std::runtime_error("a thread of the team failed") {}
};

class SpinBarrier {
 public:
  explicit SpinBarrier(int count) : count_(count) {}

  /// Returns once all `count` threads have called wait() for this round; throws TeamAborted
  /// once abort() was called.
  void wait() {
    const unsigned round = round_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == count_) {
      arrived_.store(0, std::memory_order_relaxed);
      round_.store(round + 1, std::memory_order_release);
      return;
    }
    for (int spins = 0; round_.load(std::memory_order_acquire) == round; ++spins) {
      if (aborted_.load(std::memory_order_acquire)) throw TeamAborted();
      if (spins < kSpinsBeforeYield) {
        pause();
      } else {
        std::this_thread::yield();
      }
    }
  }

  /// Releases the threads waiting now or later with TeamAborted: a member that fails calls it,
  /// so that the others do not wait for it forever.
  void abort() { aborted_.store(true, std::memory_order_release); }
  /// Makes an aborted barrier usable again; only while no thread waits on it.
  void reset() {
    aborted_.store(false, std::memory_order_relaxed);
    arrived_.store(0, std::memory_order_relaxed);
  }

 private:
  static constexpr int kSpinsBeforeYield = 1 << 14;
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
  }

  const int count_;
  std::atomic<int> arrived_{0};
  std::atomic<unsigned> round_{0};
  std::atomic<bool> aborted_{false};
};

struct Team {
  int member = 0;
  int size = 1;
  SpinBarrier* barrier = nullptr;  // shared by the members; unused when size == 1

  /// Waits until every member has reached this point.
  void sync() const {
    if (size > 1) barrier->wait();
  }

  /// This member's part [first, first + count) of n entries: contiguous parts in member order,
  /// cut at multiples of `align` (the matrix kernel's vector width, nn/gemm.hpp) where possible.
  std::pair<Index, Index> share(Index n, Index align = 16) const {
    if (align < 1) align = 1;
    const auto cut = [&](int m) -> Index {
      if (m >= size) return n;
      const Index even = n * m / size;
      const Index rounded = (even + align / 2) / align * align;
      return rounded < n ? rounded : n;
    };
    const Index first = cut(member);
    return {first, cut(member + 1) - first};
  }
};

}  // namespace corrmp::nn
