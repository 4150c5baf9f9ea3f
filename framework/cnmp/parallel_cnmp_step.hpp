// One Adam update of a CNMP (paper, Section III-A; training as in cnmp/cnmp_trainer.hpp) on the
// cores a run has, so that a single large network, such as the monolithic baseline's, does not
// leave a core idle.
//
// With W workers the update runs as a team (nn/team.hpp): each member computes its share of
// every layer's output columns in the forward pass, of the parameter-gradient rows and
// input-gradient columns in the backward pass, then updates its share of the parameters by Adam
// and zeroes their gradients for the next update. Every entry is computed by the same operations
// as with one worker (the products sum over the same index in the same order, nn/gemm.hpp, and
// Adam's shares are cut on its range boundaries, nn/adam.hpp), so the results are identical
// whatever W: the parallel update changes the speed of a run, never its numbers. Cutting the
// layers rather than the batch keeps each core's share of the weights, gradients and Adam
// moments at 1/W; each would otherwise stream all of them, which is what bounds an update of
// this size.
//
// Which is faster, the team or one thread alone, depends on the machine's load: on a shared
// host the second core can be slowed or taken away for seconds, and the team then runs slower
// than one thread. Both give the same bits, so the update times them in turn: of every
// `probe_every` updates, the first `probe_updates` run on the team, the next `probe_updates` on
// one thread, and the faster by the median update time runs the rest (the median, so that one
// update the host stalled for milliseconds does not decide).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "cnmp/batch_sampler.hpp"
#include "core/worker_pool.hpp"
#include "nn/adam.hpp"
#include "nn/team.hpp"

namespace corrmp {

// Whether the team's second thread has a core of its own, or borrows one a thread that waits
// for others' work lends (core/thread_budget.hpp: SpareThread). A borrowing update runs alone
// until a core is lent (it asks at the start of every `probe_every` updates), and gives it back
// when one thread alone was the faster in the probe, or at once when the lender stops waiting.
enum class TeamCores { own, borrowed };

class ParallelCnmpStep {
 public:
  // Updates `network` (which must outlive this) by Adam on `workers` >= 1 threads; on one where
  // float products are not split-exact (nn::gemm_float_split_exact), which keeps the bits.
  ParallelCnmpStep(Cnmp<float>& network, double learning_rate, int workers,
                   TeamCores cores = TeamCores::own, int64_t probe_every = 4000,
                   int64_t probe_updates = 50);
  ~ParallelCnmpStep();
  ParallelCnmpStep(const ParallelCnmpStep&) = delete;
  ParallelCnmpStep& operator=(const ParallelCnmpStep&) = delete;

  void set_learning_rate(double learning_rate) { adam_.set_learning_rate(learning_rate); }

  // One update on the batch `sampler` drew last; returns the batch's loss. When the loss is not
  // finite the weights, gradients and Adam's state are left unchanged. With two workers or more
  // the network's gradients must be zero when step() is called (each update zeroes them after
  // use, in the same pass as Adam): nothing else may accumulate gradients into the network
  // between updates.
  float step(const BatchSampler& sampler);

  int workers() const { return pool_->size(); }
  // How many updates ran on the team so far.
  int64_t team_updates() const { return team_updates_; }

 private:
  // The update on one thread: zero the gradients, a forward and backward pass, Adam's step.
  float step_alone(const BatchSampler& sampler);
  // The update on the team (the gradients zero on entry and on return).
  float step_as_team(const BatchSampler& sampler);
  // Adds Adam's update to blocks [first, last) of the parameters (its step begun) and zeroes
  // their gradients.
  void update(size_t first, size_t last);

  Cnmp<float>& network_;
  std::vector<nn::Parameter<float>> params_;
  nn::Adam<float> adam_;
  std::unique_ptr<WorkerPool> pool_;
  nn::SpinBarrier barrier_;
  std::vector<nn::Adam<float>::Range> blocks_;  // every parameter entry, in parameter order

  int64_t probe_every_, probe_updates_;
  int64_t updates_ = 0, team_updates_ = 0;
  std::vector<double> team_seconds_, alone_seconds_;  // each update's, in the current probe
  bool team_faster_ = true;
  TeamCores cores_;
  bool borrowed_ = false;        // a core lent to the team (TeamCores::borrowed)
  bool gradients_zero_ = false;  // as the team expects them on entry
};

}  // namespace corrmp
