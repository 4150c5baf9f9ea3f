// Gaussian negative log-likelihood, the CNMP training loss: the decoder predicts a mean and a
// raw spread value for every target point and dimension (paper, Section "General Framework",
// after Seker et al., "Conditional Neural Movement Primitives", RSS 2019).
//
// For M = N x D predictions (mean mu, raw r) and targets y, with c >= 0 the softplus scale:
//   sigma = min_std + c softplus(r)
//   z     = (y - mu) / sigma
//   L     = (1 / M) sum [ log sigma + z^2 / 2 + log(2 pi) / 2 ]
//   dL/dmu = -(1 / M) z / sigma
//   dL/dr  =  (1 / M) (1 - z^2) / sigma * c sigmoid(r)
// The defaults give sigma = 0.01 + softplus(r); min_std = 0.1, c = 0.9 gives the
// sigma = 0.1 + 0.9 softplus(r) of some public CNMP code. Sums are accumulated in double.
// Matrices follow nn/tensor.hpp; mean, raw, target, d_mean and d_raw all have the same shape
// and may be column blocks of wider matrices (e.g. the two halves of a decoder output).
#pragma once

#include "nn/tensor.hpp"

namespace corrmp::nn {

template <class S>
class GaussianNll {
 public:
  /// sigma = min_std + softplus_scale * softplus(raw); min_std > 0 keeps the loss bounded.
  explicit GaussianNll(double min_std = 0.01, double softplus_scale = 1.0);

  /// sigma for one raw value.
  S std_from_raw(S raw) const;
  /// sigma element-wise; std may alias raw.
  void std_from_raw(ConstMatRef<S> raw, MatRef<S> std) const;

  /// The mean loss L.
  S value(ConstMatRef<S> mean, ConstMatRef<S> raw, ConstMatRef<S> target) const;
  /// The mean loss L; writes dL/dmean and dL/draw (overwritten, not accumulated).
  S value_and_grad(ConstMatRef<S> mean, ConstMatRef<S> raw, ConstMatRef<S> target, MatRef<S> d_mean,
                   MatRef<S> d_raw) const;

  double min_std() const { return min_std_; }
  double softplus_scale() const { return softplus_scale_; }

 private:
  void check(const char* where, ConstMatRef<S> mean, ConstMatRef<S> raw,
             ConstMatRef<S> target) const;

  double min_std_;
  double softplus_scale_;
};

extern template class GaussianNll<float>;
extern template class GaussianNll<double>;

}  // namespace corrmp::nn
