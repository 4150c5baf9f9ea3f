// Per-dimension standardisation with training statistics: the CNMP learns
// y and contexts as (v - offset) / scale, so one standard-deviation floor and
// one learning rate suit trajectories in metres and contexts of any unit.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace corrmp {

struct Normaliser {
  Eigen::RowVectorXd offset;
  Eigen::RowVectorXd scale;

  // Mean and standard deviation of the rows; dimensions that do not vary get
  // scale 1 so they pass through unchanged apart from the offset.
  static Normaliser fit(const Eigen::MatrixXd& rows);
  static Normaliser identity(int dims);

  Eigen::MatrixXd apply(const Eigen::MatrixXd& rows) const;
  Eigen::MatrixXd invert(const Eigen::MatrixXd& rows) const;
  int dims() const { return static_cast<int>(offset.size()); }
};

}  // namespace corrmp
