// The first layer of the CNMP decoder (paper, Section III-A and Fig. 3), with its representation
// part computed once per task instead of once per target.
//
// The decoder's input for target t of task b is [r_b, q_t]: the representation r_b (the mean
// encoding of the task's observations) and q_t = [c_b, x_t] (the context and the query). With the
// layer's weight W = [W_r | W_q] (PyTorch order, nn/linear.hpp) and bias b:
//   forward:   p_b = r_b W_r^T  (once per task),   z_t = q_t W_q^T + p_b + b
//   backward:  with g_t = dL/dz_t and s_b = sum of g_t over task b's targets,
//              dW_r += s^T R,   dW_q += g^T Q,   db += sum_b s_b,   dL/dr_b = s_b W_r
// which are the layer's results on the repeated rows [r_b, q_t], the sums regrouped. A training
// batch of the default configs (8 tasks, 1-10 targets each) repeats each r_b 5.5 times on
// average, and the representation part of this layer was about a fifth of a CNMP update's
// multiply-adds; a prediction of 200 points repeats it 200 times.
//
// The *_part calls cut the work among a team's members (nn/team.hpp) by output columns (or, for
// dL/dr, representation columns). Where float products run on nn/gemm.hpp's split-exact kernel
// (the only builds that run a team), every entry is computed exactly as a whole call computes
// it: the sums over targets and tasks are plain loops in row order.
#pragma once

#include <string>
#include <vector>

#include "nn/buffer.hpp"
#include "nn/linear.hpp"
#include "nn/parameter.hpp"
#include "nn/rng.hpp"
#include "nn/tensor.hpp"

namespace corrmp {

template <class S>
class DecoderFirstLayer {
 public:
  /// Inputs [r (representation_size), q (query_size)] -> `out` outputs, initialised as
  /// nn::Linear (same draws from rng).
  DecoderFirstLayer(nn::Index representation_size, nn::Index query_size, nn::Index out,
                    nn::Rng& rng);

  /// Shapes the per-task buffers for a batch of `tasks`, on one thread before a team's parts.
  void prepare(nn::Index tasks);

  /// Columns [first, first + count) of z (targets x out) for representations r (tasks x
  /// representation_size) and queries q (targets x query_size), task b owning the next
  /// target_counts[b] rows.
  void forward_part(nn::ConstMatRef<S> r, nn::ConstMatRef<S> q,
                    const std::vector<int>& target_counts, nn::MatRef<S> z, nn::Index first,
                    nn::Index count);
  /// Given g = dL/dz, accumulates the rows [first, first + count) of dL/dW and those entries of
  /// dL/db, and keeps those columns of s for representation_grad_part.
  void backward_params_part(nn::ConstMatRef<S> r, nn::ConstMatRef<S> q, nn::ConstMatRef<S> g,
                            const std::vector<int>& target_counts, nn::Index first,
                            nn::Index count);
  /// Columns [first, first + count) of dL/dr (tasks x representation_size), once every member's
  /// backward_params_part has finished.
  void representation_grad_part(nn::MatRef<S> dr, nn::Index first, nn::Index count);

  /// {prefix + "weight" [out, representation + query], prefix + "bias" [out]}.
  std::vector<nn::Parameter<S>> parameters(const std::string& prefix) {
    return linear_.parameters(prefix);
  }
  nn::Index num_parameters() const { return linear_.num_parameters(); }
  nn::Index out_features() const { return linear_.out_features(); }

 private:
  nn::Linear<S> linear_;  // W = [W_r | W_q] and b
  nn::Index representation_size_;
  nn::Buffer<S> task_products_;  // p: tasks x out
  nn::Buffer<S> task_grads_;     // s: tasks x out
};

extern template class DecoderFirstLayer<float>;
extern template class DecoderFirstLayer<double>;

}  // namespace corrmp
