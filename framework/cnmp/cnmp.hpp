// The Conditional Neural Movement Primitive with a context input (paper,
// Section III-A and Fig. 3; Seker et al., RSS 2019).
//
// Observations o_i = (x_i, y_i) of a trajectory are encoded one by one and
// averaged into a representation r; the decoder maps (r, context c, query x_q)
// to the mean and standard deviation of y at x_q:
//   r = (1/n) sum_i E(x_i, y_i)
//   (mu, raw) = D([r, c, x_q]),   sigma = min_std + softplus(raw)
//   loss = mean over targets and dimensions of -log N(y_q; mu, sigma)
// Backward: dL/dr_b = sum_j dL/dinput_j[0:w] over the targets j of task b, and
// each observation row of task b receives dL/dr_b / n_b. The decoder's first layer
// computes its r_b part once per task (cnmp/decoder_first_layer.hpp).
//
// A batch holds B tasks; task b has counts.observations[b] observation rows and
// counts.targets[b] target rows, stored contiguously in task order. No heap
// allocation in train_step once the largest batch has been seen.
#pragma once

#include <optional>
#include <vector>

#include "cnmp/cnmp_architecture.hpp"
#include "cnmp/decoder_first_layer.hpp"
#include "nn/buffer.hpp"
#include "nn/gaussian_nll.hpp"
#include "nn/mlp.hpp"
#include "nn/model_file.hpp"
#include "nn/parameter.hpp"
#include "nn/team.hpp"

namespace corrmp {

struct CnmpBatchCounts {
  std::vector<int> observations;  // per task
  std::vector<int> targets;       // per task (unused by predict)
};

template <class S>
class Cnmp {
 public:
  using Mat = nn::Mat<S>;

  Cnmp(const CnmpArchitecture& architecture, nn::Rng& rng);

  // One forward and backward pass; accumulates parameter gradients and returns
  // the loss. observations: rows (x, y) of size d_x + d_y; contexts: B x
  // d_context; target_x: rows of size d_x; target_y: rows of size d_y.
  S train_step(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
               nn::ConstMatRef<S> target_x, nn::ConstMatRef<S> target_y,
               const CnmpBatchCounts& counts);

  // train_step cut among the members of a team of threads (nn/team.hpp), with the same loss and
  // gradients: prepare_step on one thread, then train_step_part on every member, which returns
  // the loss once all members have finished. The arguments must stay unchanged in between.
  void prepare_step(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                    nn::ConstMatRef<S> target_x, const CnmpBatchCounts& counts);
  S train_step_part(nn::ConstMatRef<S> target_y, const CnmpBatchCounts& counts,
                    const nn::Team& team);

  // Prediction for one task: conditions on `observations` (n x (d_x + d_y)) and
  // `context` (1 x d_context), queries `query_x` (T x d_x); writes T x d_y.
  void predict(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> context,
               nn::ConstMatRef<S> query_x, Mat& mean, Mat& std);

  std::vector<nn::Parameter<S>> parameters();
  int64_t parameter_count() const;
  const CnmpArchitecture& architecture() const { return architecture_; }

  // Architecture hyperparameters and weights, as a model file (nn/model_file.hpp).
  void save_to(nn::ModelFile& file);
  // Loads weights; throws std::runtime_error when the file's architecture differs.
  void load_from(const nn::ModelFile& file);
  static CnmpArchitecture architecture_of(const nn::ModelFile& file);

 private:
  // Shapes the buffers of a forward pass and copies its inputs, on one thread.
  void prepare_forward(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                       nn::ConstMatRef<S> target_x, const CnmpBatchCounts& counts);
  // Encodes the observations, averages them per task and decodes, cut among the team.
  void forward_part(const CnmpBatchCounts& counts, const nn::Team& team);

  // The context and query of each target row, into queries_.
  void fill_queries(nn::ConstMatRef<S> contexts, nn::ConstMatRef<S> target_x,
                    const std::vector<int>& target_counts);
  // r_b, the mean of task b's encodings (encoder output), into representation_.
  void average_encodings(const std::vector<int>& observation_counts);
  // Columns [first, first + count) of dL/dr_b spread over task b's encodings into d_encoded_.
  void spread_representation_grad(const CnmpBatchCounts& counts, nn::Index first, nn::Index count);

  // The decoder's first layer's output: the input of the layers after it, or the decoder's
  // output when it has one layer.
  nn::MatMap<S> first_layer_output();
  nn::ConstMatMap<S> output() const;

  CnmpArchitecture architecture_;
  nn::Mlp<S> encoder_;
  DecoderFirstLayer<S> decoder_first_;
  std::optional<nn::Mlp<S>> decoder_rest_;  // the decoder's other layers (none with one layer)
  nn::GaussianNll<S> loss_;
  nn::Buffer<S> representation_;    // tasks x width
  nn::Buffer<S> queries_;           // targets x (d_context + d_x)
  nn::Buffer<S> one_layer_output_;  // targets x 2 d_y, for a decoder of one layer
  nn::Buffer<S> d_output_;          // targets x 2 d_y
  nn::Buffer<S> d_first_;           // targets x first layer outputs: dL/dz of that layer
  nn::Buffer<S> d_representation_;  // tasks x width
  nn::Buffer<S> d_encoded_;         // observations x width
  S shared_loss_ = S(0);            // train_step_part's loss, written by member 0
};

extern template class Cnmp<float>;
extern template class Cnmp<double>;

}  // namespace corrmp
