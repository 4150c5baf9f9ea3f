// Trajectory errors (trajectory_error.hpp).
#include "evaluation/trajectory_error.hpp"

namespace corrmp {

double mean_row_distance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).rowwise().norm().mean();
}

}  // namespace corrmp
