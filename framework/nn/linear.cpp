// Fully connected layer (formulas in nn/linear.hpp).
#include "nn/linear.hpp"

#include <stdexcept>

#include "nn/check.hpp"
#include "nn/gemm.hpp"

namespace corrmp::nn {

template <class S>
Linear<S>::Linear(Index in, Index out, Rng& rng)
    : weight_(out, in), bias_(out), weight_grad_(out, in), bias_grad_(out) {
  if (in <= 0 || out <= 0) throw std::invalid_argument("Linear: sizes must be positive");
  const double bound = default_init_bound(in);
  fill_uniform(rng, bound, weight_.data(), weight_.size());
  fill_uniform(rng, bound, bias_.data(), bias_.size());
  weight_grad_.setZero();
  bias_grad_.setZero();
}

template <class S>
void Linear<S>::forward(ConstMatRef<S> x, MatRef<S> y) const {
  check_shape("Linear::forward", "x", x, x.rows(), in_features());
  check_shape("Linear::forward", "y", y, x.rows(), out_features());
  forward_part(x, y, 0, out_features());
}

template <class S>
void Linear<S>::forward_part(ConstMatRef<S> x, MatRef<S> y, Index first, Index count) const {
  if (count == 0) return;
  auto part = y.middleCols(first, count);
  gemm<S>(x, Op::kPlain, weight_.middleRows(first, count), Op::kTransposed, part, false,
          gemm_scratch<S>());
  part.rowwise() += bias_.segment(first, count);
}

template <class S>
void Linear<S>::accumulate_param_grad(ConstMatRef<S> x, ConstMatRef<S> dy) {
  check_shape("Linear::backward", "x", x, x.rows(), in_features());
  check_shape("Linear::backward", "dy", dy, x.rows(), out_features());
  gemm<S>(dy, Op::kTransposed, x, Op::kPlain, weight_grad_, true, gemm_scratch<S>());
  accumulate_bias_grad(dy);
}

template <class S>
void Linear<S>::weight_grad_part(ConstMatRef<S> x, ConstMatRef<S> dy, Index first, Index count) {
  if (count == 0) return;
  auto part = weight_grad_.middleRows(first, count);
  gemm<S>(dy.middleCols(first, count), Op::kTransposed, x, Op::kPlain, part, true,
          gemm_scratch<S>());
}

template <class S>
void Linear<S>::accumulate_bias_grad(ConstMatRef<S> dy) {
  bias_grad_.noalias() += dy.colwise().sum();
}

template <class S>
void Linear<S>::input_grad(ConstMatRef<S> dy, MatRef<S> dx) const {
  check_shape("Linear::backward", "dy", dy, dy.rows(), out_features());
  check_shape("Linear::backward", "dx", dx, dy.rows(), in_features());
  input_grad_part(dy, dx, 0, in_features());
}

template <class S>
void Linear<S>::input_grad_part(ConstMatRef<S> dy, MatRef<S> dx, Index first, Index count) const {
  if (count == 0) return;
  auto part = dx.middleCols(first, count);
  gemm<S>(dy, Op::kPlain, weight_.middleCols(first, count), Op::kPlain, part, false,
          gemm_scratch<S>());
}

template <class S>
void Linear<S>::backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx) {
  accumulate_param_grad(x, dy);
  input_grad(dy, dx);
}

template <class S>
std::vector<Parameter<S>> Linear<S>::parameters(const std::string& prefix) {
  return {{prefix + "weight", {out_features(), in_features()}, weight_.data(), weight_grad_.data()},
          {prefix + "bias", {out_features()}, bias_.data(), bias_grad_.data()}};
}

template class Linear<float>;
template class Linear<double>;

}  // namespace corrmp::nn
