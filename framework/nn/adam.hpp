// Adam optimiser (Kingma & Ba), used for both the CNMPs (lr 1e-4) and the autoencoder
// (lr 3e-4) in the paper (Sections "Learning the Context" and the training parameters table).
//
// Matches torch.optim.Adam (amsgrad off). Weight decay is the L2 form PyTorch's Adam uses
// (added to the gradient, NOT decoupled as in AdamW). At step t = 1, 2, ... for each entry:
//   g   = grad + weight_decay * p
//   m   = beta1 m + (1 - beta1) g
//   v   = beta2 v + (1 - beta2) g^2
//   p  -= lr / (1 - beta1^t) * m / (sqrt(v) / sqrt(1 - beta2^t) + eps)
// The moment buffers are allocated in the constructor; step() and zero_grad() never allocate.
// step() flushes subnormal floats to zero while it runs (nn/denormals.hpp): without that, the
// decayed second moments of late training make it several times slower on x86.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "nn/parameter.hpp"
#include "nn/tensor.hpp"

namespace corrmp::nn {

struct AdamOptions {
  double learning_rate = 1e-3;
  double beta1 = 0.9;
  double beta2 = 0.999;
  double eps = 1e-8;
  double weight_decay = 0.0;  ///< L2 penalty added to the gradient (PyTorch Adam semantics)
};

template <class S>
class Adam {
 public:
  /// Optimises `params` (views into layers that must outlive the optimiser).
  Adam(std::vector<Parameter<S>> params, const AdamOptions& options);

  /// Sets every parameter gradient to zero.
  void zero_grad();
  /// One update of every parameter from its accumulated gradient: begin_step(), then
  /// update_range over all entries.
  void step();
  /// Starts the next step for update_range (advances step_count()).
  void begin_step();
  /// Updates entries [begin, end) of parameter k as step() does in the step begun last. Calls on
  /// disjoint ranges may run on different threads at once. With begin a multiple of
  /// kRangeAlignment and end one too or the parameter's size, the result is exactly step()'s,
  /// so splitting a step among threads that way does not change it (other ranges can differ in
  /// the last bit: the compiler contracts the scalar and the vectorised code differently).
  void update_range(std::size_t k, Index begin, Index end);
  /// step() updates each parameter in pieces of this many entries, from its first.
  static constexpr Index kRangeAlignment = 2048;

  /// Entries [begin, end) of parameter `parameter`: a unit of work for update_range.
  struct Range {
    std::size_t parameter;
    Index begin;
    Index end;
  };
  /// Every entry of the parameters, in parameter order, in ranges of `size` entries (a multiple
  /// of kRangeAlignment, so that update_range on them is exactly step()).
  static std::vector<Range> ranges(const std::vector<Parameter<S>>& params, Index size);

  std::int64_t step_count() const { return step_count_; }
  const AdamOptions& options() const { return options_; }
  void set_learning_rate(double learning_rate) { options_.learning_rate = learning_rate; }
  const std::vector<Parameter<S>>& parameters() const { return params_; }

 private:
  std::vector<Parameter<S>> params_;
  AdamOptions options_;
  std::vector<Vec<S>> first_moment_;   // m, one vector per parameter
  std::vector<Vec<S>> second_moment_;  // v, one vector per parameter
  std::int64_t step_count_ = 0;
  // The step's factors (begin_step): lr / (1 - beta1^t) and 1 / sqrt(1 - beta2^t).
  S step_size_ = S(0);
  S inv_sqrt_bc2_ = S(0);

  void update_entries(std::size_t k, Index begin, Index end);  // without the denormal scope
};

extern template class Adam<float>;
extern template class Adam<double>;

}  // namespace corrmp::nn
