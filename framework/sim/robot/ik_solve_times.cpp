// Wall time of inverse-kinematics solves (ik_solve_times.hpp).
#include "sim/robot/ik_solve_times.hpp"

#include <algorithm>
#include <cmath>

namespace corrmp {

void IkSolveTimes::add(double seconds) {
  const double decades = std::log10(std::max(seconds, kLowest) / kLowest);
  const int last = static_cast<int>(bins_.size()) - 1;
  const int bin = std::clamp(static_cast<int>(decades * kBinsPerDecade), 0, last);
  const std::lock_guard<std::mutex> lock(mutex_);
  ++solves_;
  total_ += seconds;
  ++bins_[static_cast<size_t>(bin)];
}

int64_t IkSolveTimes::solves() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return solves_;
}

double IkSolveTimes::mean_seconds() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return solves_ > 0 ? total_ / static_cast<double>(solves_) : 0.0;
}

double IkSolveTimes::median_seconds() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (solves_ == 0) return 0.0;
  int64_t below = 0;
  size_t bin = 0;
  for (; bin + 1 < bins_.size(); ++bin) {
    below += bins_[bin];
    if (2 * below >= solves_) break;
  }
  // The bin's geometric centre.
  return kLowest * std::pow(10.0, (static_cast<double>(bin) + 0.5) / kBinsPerDecade);
}

}  // namespace corrmp
