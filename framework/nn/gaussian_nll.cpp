// Gaussian negative log-likelihood (formulas in nn/gaussian_nll.hpp).
#include "nn/gaussian_nll.hpp"

#include <cmath>
#include <stdexcept>

#include "nn/activation.hpp"
#include "nn/check.hpp"

namespace corrmp::nn {
namespace {

constexpr double kHalfLogTwoPi = 0.91893853320467274178;  // log(2 pi) / 2

}  // namespace

template <class S>
GaussianNll<S>::GaussianNll(double min_std, double softplus_scale)
    : min_std_(min_std), softplus_scale_(softplus_scale) {
  if (!(min_std > 0.0)) throw std::invalid_argument("GaussianNll: min_std must be > 0");
  if (!(softplus_scale >= 0.0))
    throw std::invalid_argument("GaussianNll: softplus_scale must be >= 0");
}

template <class S>
S GaussianNll<S>::std_from_raw(S raw) const {
  return static_cast<S>(min_std_) + static_cast<S>(softplus_scale_) * softplus(raw);
}

template <class S>
void GaussianNll<S>::std_from_raw(ConstMatRef<S> raw, MatRef<S> std) const {
  check_shape("GaussianNll::std_from_raw", "std", std, raw.rows(), raw.cols());
  std = raw.unaryExpr([this](S r) { return std_from_raw(r); });
}

template <class S>
void GaussianNll<S>::check(const char* where, ConstMatRef<S> mean, ConstMatRef<S> raw,
                           ConstMatRef<S> target) const {
  check_shape(where, "raw", raw, mean.rows(), mean.cols());
  check_shape(where, "target", target, mean.rows(), mean.cols());
  if (mean.size() == 0) throw std::invalid_argument(std::string(where) + ": empty batch");
}

template <class S>
S GaussianNll<S>::value(ConstMatRef<S> mean, ConstMatRef<S> raw, ConstMatRef<S> target) const {
  check("GaussianNll::value", mean, raw, target);
  double sum = 0.0;
  for (Index i = 0; i < mean.rows(); ++i) {
    for (Index j = 0; j < mean.cols(); ++j) {
      const S sigma = std_from_raw(raw(i, j));
      const S z = (target(i, j) - mean(i, j)) / sigma;
      sum += static_cast<double>(std::log(sigma) + S(0.5) * z * z);
    }
  }
  return static_cast<S>(sum / static_cast<double>(mean.size()) + kHalfLogTwoPi);
}

template <class S>
S GaussianNll<S>::value_and_grad(ConstMatRef<S> mean, ConstMatRef<S> raw, ConstMatRef<S> target,
                                 MatRef<S> d_mean, MatRef<S> d_raw) const {
  check("GaussianNll::value_and_grad", mean, raw, target);
  check_shape("GaussianNll::value_and_grad", "d_mean", d_mean, mean.rows(), mean.cols());
  check_shape("GaussianNll::value_and_grad", "d_raw", d_raw, mean.rows(), mean.cols());
  const S inv_count = static_cast<S>(1.0 / static_cast<double>(mean.size()));
  const S scale = static_cast<S>(softplus_scale_);
  double sum = 0.0;
  for (Index i = 0; i < mean.rows(); ++i) {
    for (Index j = 0; j < mean.cols(); ++j) {
      const S r = raw(i, j);
      const S sigma = std_from_raw(r);
      const S inv_sigma = S(1) / sigma;
      const S z = (target(i, j) - mean(i, j)) * inv_sigma;
      sum += static_cast<double>(std::log(sigma) + S(0.5) * z * z);
      d_mean(i, j) = -inv_count * z * inv_sigma;
      d_raw(i, j) = inv_count * (S(1) - z * z) * inv_sigma * scale * sigmoid(r);
    }
  }
  return static_cast<S>(sum / static_cast<double>(mean.size()) + kHalfLogTwoPi);
}

template class GaussianNll<float>;
template class GaussianNll<double>;

}  // namespace corrmp::nn
