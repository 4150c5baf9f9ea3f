// The CNMP training sampler of the public CNMP code (Seker et al., RSS 2019):
// per update, B demonstrations drawn uniformly; n observations uniform in
// 1..max_observations and m targets uniform in 1..max_targets (shared by the
// batch, capped by each trajectory's length), taken disjoint from one random
// permutation of the time steps. Fills preallocated matrices: no allocation per
// update.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "cnmp/cnmp.hpp"
#include "cnmp/cnmp_trainer.hpp"
#include "core/seeds.hpp"

namespace corrmp {

// A trajectory in normalised units, ready for batches.
struct NormalisedTrajectory {
  nn::Mat<float> xy;       // T x (d_x + d_y)
  nn::Mat<float> context;  // 1 x d_context
};

class BatchSampler {
 public:
  BatchSampler(const std::vector<NormalisedTrajectory>& data, const CnmpArchitecture& a,
               const CnmpTrainingParams& p)
      : data_(data), a_(a), p_(p) {
    int longest = 0;
    for (const auto& t : data) longest = std::max(longest, static_cast<int>(t.xy.rows()));
    permutation_.resize(longest);
    // A draw never takes more points than a trajectory has (n <= T - 1, n + m <= T), so the
    // buffers hold at most that: max_targets = 1e9 means "all points", not 1e9 rows.
    const Eigen::Index batch = p.batch_size;
    const Eigen::Index max_n = std::max(1, std::min(p.max_observations, longest - 1));
    const Eigen::Index max_m = std::max(1, std::min(p.max_targets, longest));
    observations_.resize(batch * max_n, a.d_x + a.d_y);
    contexts_.resize(p.batch_size, a.d_context);
    target_x_.resize(batch * max_m, a.d_x);
    target_y_.resize(batch * max_m, a.d_y);
    counts_.observations.resize(p.batch_size);
    counts_.targets.resize(p.batch_size);
  }

  void draw(Rng& rng) {
    const int n_draw = static_cast<int>(rng.uniform_int(1, p_.max_observations));
    const int m_draw = static_cast<int>(rng.uniform_int(1, p_.max_targets));
    int obs_row = 0, target_row = 0;
    for (int b = 0; b < p_.batch_size; ++b) {
      const auto& t = data_[rng.uniform_int(0, static_cast<int64_t>(data_.size()) - 1)];
      const int steps = static_cast<int>(t.xy.rows());
      const int n = std::min(n_draw, steps - 1);
      const int m = std::min(m_draw, steps - n);
      std::iota(permutation_.begin(), permutation_.begin() + steps, 0);
      for (int i = 0; i < n + m; ++i) {  // partial Fisher-Yates: the first n + m positions
        std::swap(permutation_[i], permutation_[rng.uniform_int(i, steps - 1)]);
      }
      for (int i = 0; i < n; ++i) observations_.row(obs_row++) = t.xy.row(permutation_[i]);
      for (int j = 0; j < m; ++j) {
        const auto& row = t.xy.row(permutation_[n + j]);
        target_x_.row(target_row) = row.leftCols(a_.d_x);
        target_y_.row(target_row++) = row.rightCols(a_.d_y);
      }
      if (a_.d_context > 0) contexts_.row(b) = t.context;
      counts_.observations[b] = n;
      counts_.targets[b] = m;
    }
    obs_rows_ = obs_row;
    target_rows_ = target_row;
  }

  // One forward and backward pass of `network` on the drawn batch; returns the loss.
  float step(Cnmp<float>& network) const {
    return network.train_step(observations(), contexts_, target_x(), target_y(), counts_);
  }

  // The drawn batch, as step() passes it to the network.
  nn::ConstMatMap<float> observations() const {
    return nn::ConstMatMap<float>(observations_.data(), obs_rows_, observations_.cols());
  }
  const nn::Mat<float>& contexts() const { return contexts_; }
  nn::ConstMatMap<float> target_x() const {
    return nn::ConstMatMap<float>(target_x_.data(), target_rows_, target_x_.cols());
  }
  nn::ConstMatMap<float> target_y() const {
    return nn::ConstMatMap<float>(target_y_.data(), target_rows_, target_y_.cols());
  }
  const CnmpBatchCounts& counts() const { return counts_; }

  int observation_rows() const { return obs_rows_; }
  int target_rows() const { return target_rows_; }

 private:
  const std::vector<NormalisedTrajectory>& data_;
  CnmpArchitecture a_;
  CnmpTrainingParams p_;
  std::vector<int> permutation_;
  nn::Mat<float> observations_, contexts_, target_x_, target_y_;
  CnmpBatchCounts counts_;
  int obs_rows_ = 0, target_rows_ = 0;
};

}  // namespace corrmp
