// CNMP updates computed by a team of threads (parallel_cnmp_step.hpp).
#include "cnmp/parallel_cnmp_step.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace corrmp {

ParallelCnmpStep::ParallelCnmpStep(Cnmp<float>& network, double learning_rate, int workers)
    : network_(network),
      params_(network.parameters()),
      adam_(params_, nn::AdamOptions{learning_rate}),
      pool_(std::max(workers, 1)),
      barrier_(std::max(workers, 1)) {
  constexpr nn::Index kBlock = nn::Adam<float>::kRangeAlignment;
  for (size_t k = 0; k < params_.size(); ++k)
    for (nn::Index begin = 0; begin < params_[k].size(); begin += kBlock)
      blocks_.push_back({k, begin, std::min(begin + kBlock, params_[k].size())});
}

void ParallelCnmpStep::update(size_t first, size_t last) {
  for (size_t b = first; b < last; ++b) {
    const UpdateBlock& block = blocks_[b];
    adam_.update_range(block.parameter, block.begin, block.end);
    float* grad = params_[block.parameter].grad;
    std::fill(grad + block.begin, grad + block.end, 0.0f);
  }
}

float ParallelCnmpStep::step(const BatchSampler& sampler) {
  if (pool_.size() == 1) {  // the plain update
    adam_.zero_grad();
    const float loss = sampler.step(network_);
    if (std::isfinite(loss)) adam_.step();
    return loss;
  }
  // The gradients are zero here: from the constructor's network (zeroed below on first use) or
  // from the previous update, which zeroed them after using them.
  if (adam_.step_count() == 0) adam_.zero_grad();
  network_.prepare_step(sampler.observations(), sampler.contexts(), sampler.target_x(),
                        sampler.counts());
  const size_t blocks = blocks_.size(), members = static_cast<size_t>(pool_.size());
  float loss = 0.0f;
  barrier_.reset();
  pool_.run([&](int member) {
    const nn::Team team{member, pool_.size(), &barrier_};
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
  return loss;
}

}  // namespace corrmp
