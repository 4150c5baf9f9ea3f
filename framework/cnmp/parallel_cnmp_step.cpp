// CNMP updates computed by a team of threads (parallel_cnmp_step.hpp).
#include "cnmp/parallel_cnmp_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "core/thread_budget.hpp"
#include "nn/gemm.hpp"

namespace corrmp {
namespace {

// The team's workers: one where float products are not split-exact, or where no thread can be
// started (one thread alone gives the same bits).
std::unique_ptr<WorkerPool> team_pool(int workers) {
  const int size = nn::gemm_float_split_exact() ? std::max(workers, 1) : 1;
  try {
    return std::make_unique<WorkerPool>(size);
  } catch (const std::system_error&) {
    return std::make_unique<WorkerPool>(1);
  }
}

// The median of `values` (reordered), or 0 for none.
double median(std::vector<double>& values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

ParallelCnmpStep::ParallelCnmpStep(Cnmp<float>& network, double learning_rate, int workers,
                                   TeamCores cores, int64_t probe_every, int64_t probe_updates)
    : network_(network),
      params_(network.parameters()),
      adam_(params_, nn::AdamOptions{learning_rate}),
      pool_(team_pool(workers)),
      barrier_(pool_->size()),
      blocks_(nn::Adam<float>::ranges(params_, nn::Adam<float>::kRangeAlignment)),
      probe_every_(std::max<int64_t>(probe_every, 1)),
      probe_updates_(std::max<int64_t>(probe_updates, 0)),
      cores_(cores) {}

ParallelCnmpStep::~ParallelCnmpStep() {
  if (borrowed_) return_spare_thread();
}

void ParallelCnmpStep::update(size_t first, size_t last) {
  for (size_t b = first; b < last; ++b) {
    const nn::Adam<float>::Range& block = blocks_[b];
    adam_.update_range(block.parameter, block.begin, block.end);
    float* grad = params_[block.parameter].grad;
    std::fill(grad + block.begin, grad + block.end, 0.0f);
  }
}

float ParallelCnmpStep::step(const BatchSampler& sampler) {
  if (pool_->size() == 1) return step_alone(sampler);
  const int64_t phase = updates_++ % probe_every_;
  if (borrowed_ && spare_thread_recalled()) borrowed_ = false;  // the lender stopped waiting
  if (phase == 0) {
    team_seconds_.clear();
    alone_seconds_.clear();
    if (cores_ == TeamCores::borrowed && !borrowed_) borrowed_ = borrow_spare_thread();
  }
  if (cores_ == TeamCores::borrowed && !borrowed_) return step_alone(sampler);
  if (phase >= 2 * probe_updates_)
    return team_faster_ ? step_as_team(sampler) : step_alone(sampler);
  const bool team = phase < probe_updates_;
  const auto start = std::chrono::steady_clock::now();
  const float loss = team ? step_as_team(sampler) : step_alone(sampler);
  (team ? team_seconds_ : alone_seconds_)
      .push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (phase + 1 == 2 * probe_updates_) {
    team_faster_ = median(team_seconds_) <= median(alone_seconds_);
    if (borrowed_ && !team_faster_) {
      return_spare_thread();  // another network may gain from it
      borrowed_ = false;
    }
  }
  return loss;
}

float ParallelCnmpStep::step_alone(const BatchSampler& sampler) {
  adam_.zero_grad();
  gradients_zero_ = false;
  const float loss = sampler.step(network_);
  if (std::isfinite(loss)) adam_.step();
  return loss;
}

float ParallelCnmpStep::step_as_team(const BatchSampler& sampler) {
  if (!gradients_zero_) adam_.zero_grad();
  gradients_zero_ = false;  // until the update below has zeroed them again
  ++team_updates_;
  network_.prepare_step(sampler.observations(), sampler.contexts(), sampler.target_x(),
                        sampler.counts());
  const size_t blocks = blocks_.size(), members = static_cast<size_t>(pool_->size());
  float loss = 0.0f;
  barrier_.reset();
  pool_->run([&](int member) {
    const nn::Team team{member, pool_->size(), &barrier_};
    try {
      // Returns once every member has finished the backward pass: all gradients are complete.
      const float batch_loss = network_.train_step_part(sampler.target_y(), sampler.counts(), team);
      if (!std::isfinite(batch_loss)) {
        if (member == 0) loss = batch_loss;
        return;
      }
      if (member == 0) {
        loss = batch_loss;
        adam_.begin_step();
      }
      team.sync();
      const size_t index = static_cast<size_t>(member);
      update(index * blocks / members, (index + 1) * blocks / members);
    } catch (const nn::TeamAborted&) {
      return;  // another member failed: its error is the one run() rethrows
    } catch (...) {
      barrier_.abort();  // the others would wait for this member forever
      throw;
    }
  });
  if (!std::isfinite(loss)) adam_.zero_grad();
  gradients_zero_ = true;
  return loss;
}

}  // namespace corrmp
