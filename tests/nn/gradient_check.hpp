// Test helpers for corrmp::nn: random matrices and central finite-difference gradient checks
// in double precision.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "nn/parameter.hpp"
#include "nn/rng.hpp"
#include "nn/tensor.hpp"

namespace corrmp::nn::testing {

using MatD = Mat<double>;

/// A rows x cols matrix with entries from U[lo, hi).
inline MatD random_matrix(Index rows, Index cols, Rng& rng, double lo = -1.0, double hi = 1.0) {
  MatD m(rows, cols);
  for (Index i = 0; i < m.size(); ++i) m.data()[i] = uniform(rng, lo, hi);
  return m;
}

/// Like random_matrix, but every |entry| >= margin (keeps ReLU kinks away from the FD stencil).
inline MatD random_matrix_away_from_zero(Index rows, Index cols, Rng& rng, double margin) {
  MatD m = random_matrix(rows, cols, rng);
  for (Index i = 0; i < m.size(); ++i) {
    double& v = m.data()[i];
    v = v < 0 ? v - margin : v + margin;
  }
  return m;
}

/// One tensor whose analytic gradient is checked: values are perturbed in place.
struct GradientCase {
  std::string label;
  double* values;
  const double* analytic;
  Index size;
};

/// The analytic gradients of the inputs and parameters of a layer.
inline std::vector<GradientCase> cases_for(const std::string& input_label, MatD& input,
                                           const MatD& input_grad,
                                           const std::vector<Parameter<double>>& params) {
  std::vector<GradientCase> cases{{input_label, input.data(), input_grad.data(), input.size()}};
  for (const Parameter<double>& p : params) cases.push_back({p.name, p.value, p.grad, p.size()});
  return cases;
}

/// ||a - b|| / max(||a||, ||b||).
inline double relative_error(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double scale = std::max(a.norm(), b.norm());
  return scale == 0.0 ? 0.0 : (a - b).norm() / scale;
}

/// Compares every case's analytic gradient with the central difference
/// (loss(v + h) - loss(v - h)) / 2h of each entry; requires relative error <= tolerance and a
/// non-zero gradient (so a backward pass that writes nothing cannot pass).
inline void expect_gradients_match(const std::function<double()>& loss,
                                   const std::vector<GradientCase>& cases, double tolerance = 1e-6,
                                   double step = 1e-6) {
  for (const GradientCase& c : cases) {
    Eigen::VectorXd numeric(c.size);
    for (Index i = 0; i < c.size; ++i) {
      const double saved = c.values[i];
      c.values[i] = saved + step;
      const double plus = loss();
      c.values[i] = saved - step;
      const double minus = loss();
      c.values[i] = saved;
      numeric[i] = (plus - minus) / (2.0 * step);
    }
    const Eigen::VectorXd analytic = Eigen::Map<const Eigen::VectorXd>(c.analytic, c.size);
    EXPECT_GT(analytic.norm(), 1e-8) << c.label << ": analytic gradient is zero";
    EXPECT_LE(relative_error(analytic, numeric), tolerance)
        << c.label << "\nanalytic: " << analytic.transpose()
        << "\nnumeric:  " << numeric.transpose();
  }
}

/// sum(weights .* y): a scalar loss whose gradient with respect to y is `weights`.
inline double weighted_sum(const MatD& y, const MatD& weights) {
  return (y.array() * weights.array()).sum();
}

}  // namespace corrmp::nn::testing
