// The wall time of inverse-kinematics solves, gathered from every robot a task
// builds (one per trial, one per thread's clone): how many, the mean and the
// median per solve. Wall time is not deterministic: it is printed in a run's
// tables, never stored with its results. Safe to add to from several threads.
#pragma once

#include <array>
#include <cstdint>
#include <mutex>

namespace corrmp {

class IkSolveTimes {
 public:
  void add(double seconds);

  int64_t solves() const;
  double mean_seconds() const;  // 0 without solves
  // The median to within 0.6% (a log-spaced histogram from 10 ns to 10 s); 0 without solves.
  double median_seconds() const;

 private:
  static constexpr int kBinsPerDecade = 200;
  static constexpr int kDecades = 9;
  static constexpr double kLowest = 1e-8;  // s, the lowest bin's lower edge

  mutable std::mutex mutex_;
  int64_t solves_ = 0;
  double total_ = 0.0;
  std::array<int64_t, kBinsPerDecade * kDecades> bins_{};  // the first and last take the rest
};

}  // namespace corrmp
