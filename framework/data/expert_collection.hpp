// How an emulated expert fills its demonstration split (paper, Section III:
// demonstrations of the whole skill, cut at the critical points): scenario
// after scenario until the training and validation sets are full, dropping
// the demonstrations that fail (a human would discard those too), and giving
// up after a bounded number of tries.
//
// The attempts run in parallel (core/thread_budget.hpp), each with its own
// random stream derived from one draw of the expert's stream and the attempt's
// index, so the split is the same whatever the number of threads: the
// successful attempts are taken in index order, the first `train` into the
// training set and the next `validation` into the validation set, exactly as
// one thread trying them one after another would.
#pragma once

#include <functional>
#include <string>

#include "core/seeds.hpp"
#include "data/demonstrations.hpp"

namespace corrmp {

struct ExpertCollection {
  int train = 0;
  int validation = 0;
  int max_attempts = 0;  // scenarios tried at most
  std::string expert;    // named in messages
};

// One attempt: draws a scenario from `rng` (the attempt's own stream) and
// demonstrates it with worker `worker`'s resources (its environment); throws
// std::runtime_error (the reason) for a demonstration to drop. Attempts of
// different workers run at the same time; one worker's run one at a time.
using ExpertAttempt = std::function<Demonstration(Rng& rng, int worker)>;

// Runs attempts on at most `workers` threads (workers >= 1). Throws when the
// sets cannot be filled within max_attempts, saying how many succeeded; an
// exception other than std::runtime_error from an attempt a single thread
// would have made is rethrown (that of the lowest attempt).
DemonstrationSplit collect_expert_demonstrations(const ExpertCollection& wanted, Rng& rng,
                                                 int workers, const ExpertAttempt& attempt);

// The attempt with index `index`'s stream, from the base value drawn from the
// expert's stream.
Rng expert_attempt_stream(uint64_t base, int index);

}  // namespace corrmp
