// Fully connected layer, the building block of the CNMP encoder and decoder (paper, Section
// "General Framework": encoder 3 layers, decoder 4 layers, width 128) and of the autoencoder's
// latent projection (Section "Learning the Context").
//
// Shapes (batch-major, see nn/tensor.hpp): x is N x in, y is N x out, W is out x in (PyTorch
// order), b has out entries.
//   forward:   y = x W^T + 1 b^T
//   backward:  dL/dW += dy^T x        (accumulated, call zero_grad between steps)
//              dL/db += 1^T dy        (column sums of dy, accumulated)
//              dL/dx  = dy W          (overwritten)
// Initialisation follows torch.nn.Linear: W and b ~ U(-1/sqrt(in), 1/sqrt(in)), W drawn first
// in row-major order, then b (draws from nn/rng.hpp, bit-identical across platforms).
// The layer keeps no activations: backward takes the forward input again, so the caller decides
// where activations live (nn/buffer.hpp) and nothing is allocated per call.
#pragma once

#include <string>
#include <vector>

#include "nn/parameter.hpp"
#include "nn/rng.hpp"
#include "nn/tensor.hpp"

namespace corrmp::nn {

template <class S>
class Linear {
 public:
  /// A layer with `in` inputs and `out` outputs, initialised like torch.nn.Linear.
  Linear(Index in, Index out, Rng& rng);

  /// y = x W^T + 1 b^T. y must be N x out; it may not alias x.
  void forward(ConstMatRef<S> x, MatRef<S> y) const;
  /// Accumulates the parameter gradients and writes dx = dy W (N x in).
  void backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx);
  /// Accumulates dL/dW and dL/db only (for a first layer whose input needs no gradient).
  void accumulate_param_grad(ConstMatRef<S> x, ConstMatRef<S> dy);
  /// Writes dx = dy W only.
  void input_grad(ConstMatRef<S> dy, MatRef<S> dx) const;

  /// The same work cut among threads (nn/team.hpp), each entry computed exactly as the whole
  /// call computes it: forward_part writes columns [first, first + count) of y,
  /// weight_grad_part accumulates those rows of dL/dW (outputs first.. of the layer) and
  /// input_grad_part writes columns [first, first + count) of dx (inputs first..).
  /// accumulate_bias_grad adds dL/db, on one thread: Eigen's column sums take an order that
  /// depends on where a block starts in memory, so they are not cut.
  void forward_part(ConstMatRef<S> x, MatRef<S> y, Index first, Index count) const;
  void weight_grad_part(ConstMatRef<S> x, ConstMatRef<S> dy, Index first, Index count);
  void accumulate_bias_grad(ConstMatRef<S> dy);
  void input_grad_part(ConstMatRef<S> dy, MatRef<S> dx, Index first, Index count) const;

  /// {prefix + "weight" [out, in], prefix + "bias" [out]}.
  std::vector<Parameter<S>> parameters(const std::string& prefix = "");

  Index in_features() const { return weight_.cols(); }
  Index out_features() const { return weight_.rows(); }
  Index num_parameters() const { return weight_.size() + bias_.size(); }

  Mat<S>& weight() { return weight_; }
  const Mat<S>& weight() const { return weight_; }
  Eigen::Matrix<S, 1, Eigen::Dynamic>& bias() { return bias_; }
  const Eigen::Matrix<S, 1, Eigen::Dynamic>& bias() const { return bias_; }
  Mat<S>& weight_grad() { return weight_grad_; }
  const Mat<S>& weight_grad() const { return weight_grad_; }
  Eigen::Matrix<S, 1, Eigen::Dynamic>& bias_grad() { return bias_grad_; }
  const Eigen::Matrix<S, 1, Eigen::Dynamic>& bias_grad() const { return bias_grad_; }

 private:
  Mat<S> weight_;
  Eigen::Matrix<S, 1, Eigen::Dynamic> bias_;
  Mat<S> weight_grad_;
  Eigen::Matrix<S, 1, Eigen::Dynamic> bias_grad_;
};

extern template class Linear<float>;
extern template class Linear<double>;

}  // namespace corrmp::nn
