// Adam optimiser (update rule in nn/adam.hpp).
#include "nn/adam.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "nn/denormals.hpp"

namespace corrmp::nn {

template <class S>
Adam<S>::Adam(std::vector<Parameter<S>> params, const AdamOptions& options)
    : params_(std::move(params)), options_(options) {
  const AdamOptions& o = options_;
  if (!(o.learning_rate >= 0.0)) throw std::invalid_argument("Adam: learning_rate must be >= 0");
  if (!(o.beta1 >= 0.0 && o.beta1 < 1.0)) throw std::invalid_argument("Adam: beta1 not in [0, 1)");
  if (!(o.beta2 >= 0.0 && o.beta2 < 1.0)) throw std::invalid_argument("Adam: beta2 not in [0, 1)");
  if (!(o.eps >= 0.0)) throw std::invalid_argument("Adam: eps must be >= 0");
  if (!(o.weight_decay >= 0.0)) throw std::invalid_argument("Adam: weight_decay must be >= 0");
  for (const Parameter<S>& p : params_) {
    first_moment_.push_back(Vec<S>::Zero(p.size()));
    second_moment_.push_back(Vec<S>::Zero(p.size()));
  }
}

template <class S>
void Adam<S>::zero_grad() {
  nn::zero_grad(params_);
}

template <class S>
void Adam<S>::step() {
  const ScopedFlushDenormals flush_denormals;
  begin_step();
  for (std::size_t k = 0; k < params_.size(); ++k) update_entries(k, 0, params_[k].size());
}

template <class S>
void Adam<S>::begin_step() {
  ++step_count_;
  const double t = static_cast<double>(step_count_);
  step_size_ = static_cast<S>(options_.learning_rate / (1.0 - std::pow(options_.beta1, t)));
  inv_sqrt_bc2_ = static_cast<S>(1.0 / std::sqrt(1.0 - std::pow(options_.beta2, t)));
}

template <class S>
std::vector<typename Adam<S>::Range> Adam<S>::ranges(const std::vector<Parameter<S>>& params,
                                                     Index size) {
  std::vector<Range> out;
  for (std::size_t k = 0; k < params.size(); ++k)
    for (Index begin = 0; begin < params[k].size(); begin += size)
      out.push_back({k, begin, std::min(begin + size, params[k].size())});
  return out;
}

template <class S>
void Adam<S>::update_range(std::size_t k, Index begin, Index end) {
  const ScopedFlushDenormals flush_denormals;
  update_entries(k, begin, end);
}

template <class S>
void Adam<S>::update_entries(std::size_t k, Index first, Index last) {
  const S beta1 = static_cast<S>(options_.beta1);
  const S beta2 = static_cast<S>(options_.beta2);
  const S step_size = step_size_, inv_sqrt_bc2 = inv_sqrt_bc2_;
  const S eps = static_cast<S>(options_.eps);
  const S decay = static_cast<S>(options_.weight_decay);
  // Work in chunks so m, v, g and p stay in L1 cache across the three array statements.
  constexpr Index kChunk = kRangeAlignment;
  const Parameter<S>& p = params_[k];
  S* value = p.value;
  S* grad = p.grad;
  S* m_data = first_moment_[k].data();
  S* v_data = second_moment_[k].data();
  for (Index begin = first; begin < last; begin += kChunk) {
    const Index n = std::min(kChunk, last - begin);
    Eigen::Map<Eigen::Array<S, Eigen::Dynamic, 1>> x(value + begin, n), g(grad + begin, n),
        m(m_data + begin, n), v(v_data + begin, n);
    if (decay != S(0)) {
      m = beta1 * m + (S(1) - beta1) * (g + decay * x);
      v = beta2 * v + (S(1) - beta2) * (g + decay * x).square();
    } else {
      m = beta1 * m + (S(1) - beta1) * g;
      v = beta2 * v + (S(1) - beta2) * g.square();
    }
    x -= step_size * m / (v.sqrt() * inv_sqrt_bc2 + eps);
  }
}

template class Adam<float>;
template class Adam<double>;

}  // namespace corrmp::nn
