// Multi-layer perceptron: Linear layers with ReLU between them and no activation after the
// last. The CNMP encoder (3 layers) of the paper is an Mlp of width 128, and so are the layers
// of its decoder (4 layers) after the first (Section "General Framework", training parameters
// table; cnmp/cnmp.hpp).
//
// sizes = {in, h1, ..., out} gives L = sizes.size() - 1 Linear layers. With a_0 = x:
//   forward:   z_i = a_{i-1} W_i^T + 1 b_i^T,   a_i = relu(z_i) for i < L,   y = z_L
//   backward:  g_L = dL/dy;  for i = L..1:  dW_i += g_i^T a_{i-1},  db_i += 1^T g_i,
//              dL/da_{i-1} = g_i W_i,  g_{i-1} = dL/da_{i-1} * [a_{i-1} > 0]
// The Mlp owns its activation and gradient buffers (nn/buffer.hpp): they grow with the largest
// batch seen and are reused afterwards, so forward/backward do not allocate once warmed up.
// forward copies x, so the caller's input may change before backward. Views returned by
// forward/backward stay valid until the next call of either.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "nn/buffer.hpp"
#include "nn/linear.hpp"
#include "nn/parameter.hpp"
#include "nn/rng.hpp"
#include "nn/team.hpp"
#include "nn/tensor.hpp"

namespace corrmp::nn {

template <class S>
class Mlp {
 public:
  /// Layers sizes[i] -> sizes[i + 1], initialised in order with nn/linear.hpp's default init.
  Mlp(std::vector<Index> sizes, Rng& rng);

  /// y (N x output_size()) for x (N x input_size()).
  ConstMatMap<S> forward(ConstMatRef<S> x);
  /// Accumulates all parameter gradients for dL/dy = dy (N x output_size(), N of the last
  /// forward) and returns dL/dx (N x input_size()).
  ConstMatMap<S> backward(ConstMatRef<S> dy);
  /// Like backward, but skips dL/dx (one matrix product fewer), e.g. for a CNMP encoder.
  void backward_params_only(ConstMatRef<S> dy);
  /// The output of the last forward.
  ConstMatMap<S> output() const { return outputs_.back().view(); }

  /// forward and backward cut among the members of a team of threads (nn/team.hpp), with the
  /// same results: prepare(rows) shapes the buffers for a batch of `rows` on one thread, input()
  /// is then filled, and every member calls forward_part, then backward_part, which return once
  /// all members have finished (each member computes its share of every layer's output columns,
  /// parameter-gradient rows and input-gradient columns).
  void prepare(Index rows);
  MatMap<S> input() { return input_.view(); }
  void forward_part(const Team& team);
  /// Returns dL/dx when input_grad, else an empty view.
  ConstMatMap<S> backward_part(ConstMatRef<S> dy, bool input_grad, const Team& team);

  /// prefix + "layers.<i>.weight" / "layers.<i>.bias" for every layer i, numbered from
  /// first_number (for an Mlp that continues another network's layers).
  std::vector<Parameter<S>> parameters(const std::string& prefix = "", Index first_number = 0);
  Index num_parameters() const;

  const std::vector<Index>& sizes() const { return sizes_; }
  Index input_size() const { return sizes_.front(); }
  Index output_size() const { return sizes_.back(); }
  Index num_layers() const { return static_cast<Index>(layers_.size()); }
  Linear<S>& layer(Index i) { return layers_.at(static_cast<std::size_t>(i)); }
  const Linear<S>& layer(Index i) const { return layers_.at(static_cast<std::size_t>(i)); }

 private:
  ConstMatMap<S> layer_input(std::size_t i) const {
    return i == 0 ? input_.view() : outputs_[i - 1].view();
  }
  // Backward through layer i given g_i; writes dL/da_{i-1} * relu'(a_{i-1}) into dx_buffer.
  void backward_layer(std::size_t i, ConstMatRef<S> g_i, bool input_grad, Buffer<S>& dx_buffer);
  // Returns the index of the grads_ buffer holding dL/dx.
  int run_backward(ConstMatRef<S> dy, bool input_grad);

  std::vector<Index> sizes_;
  std::vector<Linear<S>> layers_;
  Buffer<S> input_;
  std::vector<Buffer<S>> outputs_;  // a_1 .. a_{L-1}, then y
  Buffer<S> grads_[2];              // ping-pong buffers for g_i and dL/da_{i-1}
};

extern template class Mlp<float>;
extern template class Mlp<double>;

}  // namespace corrmp::nn
