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
// each observation row of task b receives dL/dr_b / n_b.
//
// A batch holds B tasks; task b has counts.observations[b] observation rows and
// counts.targets[b] target rows, stored contiguously in task order. No heap
// allocation in train_step once the largest batch has been seen.
#pragma once

#include <vector>

#include "cnmp/cnmp_architecture.hpp"
#include "nn/buffer.hpp"
#include "nn/gaussian_nll.hpp"
#include "nn/mlp.hpp"
#include "nn/model_file.hpp"
#include "nn/parameter.hpp"

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
  // Encodes observations, averages per task and builds the decoder input rows.
  void forward(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
               nn::ConstMatRef<S> target_x, const std::vector<int>& observation_counts,
               const std::vector<int>& target_counts);

  // The context and query columns of the decoder input's rows.
  void fill_decoder_input(nn::MatRef<S> input, nn::ConstMatRef<S> contexts,
                          nn::ConstMatRef<S> target_x, const std::vector<int>& target_counts) const;
  // r_b, the mean of task b's encodings (encoder output), into representation_ (shaped) and the
  // first columns of its targets' decoder input rows.
  void average_encodings(nn::MatRef<S> input, const std::vector<int>& observation_counts,
                         const std::vector<int>& target_counts);
  // dL/dr_b from the decoder input gradient, spread over task b's encodings into d_encoded_
  // (shaped).
  void spread_representation_grad(nn::ConstMatRef<S> d_input, const CnmpBatchCounts& counts);

  CnmpArchitecture architecture_;
  nn::Mlp<S> encoder_;
  nn::Mlp<S> decoder_;
  nn::GaussianNll<S> loss_;
  nn::Buffer<S> representation_;  // B x width
  nn::Buffer<S> decoder_input_;   // targets x (width + d_context + d_x)
  nn::Buffer<S> d_output_;        // targets x 2 d_y
  nn::Buffer<S> d_encoded_;       // observations x width
  std::vector<int> predict_counts_{0};
  S shared_loss_ = S(0);  // train_step_part's loss, written by member 0
};

extern template class Cnmp<float>;
extern template class Cnmp<double>;

}  // namespace corrmp
