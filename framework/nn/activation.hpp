// Element-wise activations for the CNMP networks (ReLU between Linear layers) and the
// autoencoder (paper, Section "Learning the Context"), plus the scalar sigmoid / softplus used
// by the Gaussian NLL loss (nn/gaussian_nll.hpp).
//
// Each activation class template (on the scalar type S) has
//   forward(x, y):       y = f(x)                  (y may alias x: in-place is allowed)
//   backward(y, dy, dx): dx = dy * f'(x)           (dx may alias dy)
// where f'(x) is written in terms of the OUTPUT y = f(x), so in-place forward passes need not
// keep their inputs:
//   ReLU        y = max(x, 0)                    f' = [y > 0]
//   LeakyReLU   y = x if x > 0 else a x, a >= 0  f' = 1 if y > 0 else a
//   Sigmoid     y = 1 / (1 + e^-x)               f' = y (1 - y)
//   Tanh        y = tanh x                       f' = 1 - y^2
//   Softplus    y = log(1 + e^x)                 f' = sigmoid(x) = 1 - e^-y = -expm1(-y)
// Matrices follow nn/tensor.hpp; shapes of x, y, dy, dx must be equal.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "nn/tensor.hpp"

namespace corrmp::nn {

/// Logistic sigmoid, stable for large |x|.
template <class S>
S sigmoid(S x) {
  if (x >= S(0)) return S(1) / (S(1) + std::exp(-x));
  const S e = std::exp(x);
  return e / (S(1) + e);
}

/// log(1 + e^x) = max(x, 0) + log1p(e^-|x|), stable for large |x|.
template <class S>
S softplus(S x) {
  return std::max(x, S(0)) + std::log1p(std::exp(-std::abs(x)));
}

template <class S>
struct Relu {
  void forward(ConstMatRef<S> x, MatRef<S> y) const { y = x.cwiseMax(S(0)); }
  void backward(ConstMatRef<S> y, ConstMatRef<S> dy, MatRef<S> dx) const {
    dx = (y.array() > S(0)).select(dy.array(), S(0)).matrix();
  }
};

template <class S>
struct LeakyRelu {
  explicit LeakyRelu(double negative_slope = 0.01) : slope(negative_slope) {
    if (!(slope >= 0.0)) throw std::invalid_argument("LeakyRelu: negative_slope must be >= 0");
  }
  void forward(ConstMatRef<S> x, MatRef<S> y) const {
    y = (x.array() > S(0)).select(x.array(), x.array() * static_cast<S>(slope)).matrix();
  }
  void backward(ConstMatRef<S> y, ConstMatRef<S> dy, MatRef<S> dx) const {
    dx = (y.array() > S(0)).select(dy.array(), dy.array() * static_cast<S>(slope)).matrix();
  }
  double slope;
};

template <class S>
struct Sigmoid {
  // Eigen's logistic, vectorised. For float it is a rational fit on [-9, 15.7] (1 above, exp(x)
  // below), accurate to about one float ulp of 1 in absolute terms, so outputs under 1e-3 are
  // accurate only to about 1e-3 of themselves (tests/nn/activation_test.cpp). Vectorised because
  // a scalar std::exp per value made the output layer a visible part of a training step.
  void forward(ConstMatRef<S> x, MatRef<S> y) const { y = x.array().logistic().matrix(); }
  void backward(ConstMatRef<S> y, ConstMatRef<S> dy, MatRef<S> dx) const {
    dx = (dy.array() * y.array() * (S(1) - y.array())).matrix();
  }
};

template <class S>
struct Tanh {
  void forward(ConstMatRef<S> x, MatRef<S> y) const { y = x.array().tanh().matrix(); }
  void backward(ConstMatRef<S> y, ConstMatRef<S> dy, MatRef<S> dx) const {
    dx = (dy.array() * (S(1) - y.array().square())).matrix();
  }
};

template <class S>
struct Softplus {
  void forward(ConstMatRef<S> x, MatRef<S> y) const {
    y = (x.array().max(S(0)) + (-x.array().abs()).exp().log1p()).matrix();
  }
  void backward(ConstMatRef<S> y, ConstMatRef<S> dy, MatRef<S> dx) const {
    dx = (-dy.array() * (-y.array()).expm1()).matrix();
  }
};

}  // namespace corrmp::nn
