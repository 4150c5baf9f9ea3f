// How far a generated trajectory is from a reference one (the paper's Table II
// error): the Euclidean distance between their rows averaged over time, and
// its mean and max over trajectories.
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace corrmp {

struct TrajectoryError {
  double mean = 0.0;  // over trajectories of the time-averaged Euclidean error
  double max = 0.0;   // the largest time-averaged error of one trajectory
};

// Collects the time-averaged errors of trajectories into their mean and max.
class TrajectoryErrorAccumulator {
 public:
  void add(double error) {
    sum_ += error;
    max_ = std::max(max_, error);
    ++count_;
  }
  int count() const { return count_; }
  TrajectoryError result() const { return {count_ > 0 ? sum_ / count_ : 0.0, max_}; }

 private:
  double sum_ = 0.0, max_ = 0.0;
  int count_ = 0;
};

// Mean Euclidean distance between rows of two equally shaped matrices.
double mean_row_distance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

}  // namespace corrmp
