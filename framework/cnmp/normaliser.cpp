// Standardisation with training statistics.
#include "cnmp/normaliser.hpp"

#include <cmath>

namespace corrmp {

Normaliser Normaliser::fit(const Eigen::MatrixXd& rows) {
  Normaliser n;
  n.offset = rows.colwise().mean();
  n.scale = ((rows.rowwise() - n.offset).array().square().colwise().mean()).sqrt().matrix();
  for (Eigen::Index i = 0; i < n.scale.size(); ++i) {
    if (!(n.scale[i] > 1e-9)) n.scale[i] = 1.0;
  }
  return n;
}

Normaliser Normaliser::identity(int dims) {
  return Normaliser{Eigen::RowVectorXd::Zero(dims), Eigen::RowVectorXd::Ones(dims)};
}

Eigen::MatrixXd Normaliser::apply(const Eigen::MatrixXd& rows) const {
  return (rows.rowwise() - offset).array().rowwise() / scale.array();
}

Eigen::MatrixXd Normaliser::invert(const Eigen::MatrixXd& rows) const {
  return (rows.array().rowwise() * scale.array()).matrix().rowwise() + offset;
}

}  // namespace corrmp
