// Mean squared error, the autoencoder's reconstruction loss (paper, Section "Learning the
// Context") and a simple regression loss for tests and baselines.
//
// For M = N x D predictions p and targets y:
//   L     = (1 / M) sum (p - y)^2
//   dL/dp = (2 / M) (p - y)
// Sums are accumulated in double. Matrices follow nn/tensor.hpp.
#pragma once

#include "nn/tensor.hpp"

namespace corrmp::nn {

template <class S>
class MseLoss {
 public:
  /// The mean loss L.
  S value(ConstMatRef<S> prediction, ConstMatRef<S> target) const;
  /// The mean loss L; writes dL/dprediction (overwritten; may alias prediction).
  S value_and_grad(ConstMatRef<S> prediction, ConstMatRef<S> target, MatRef<S> d_prediction) const;
};

extern template class MseLoss<float>;
extern template class MseLoss<double>;

}  // namespace corrmp::nn
