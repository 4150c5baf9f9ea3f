// How an emulated expert fills its demonstration split (paper, Section III:
// demonstrations of the whole skill, cut at the critical points): scenario
// after scenario until the training and validation sets are full, dropping
// the demonstrations that fail (a human would discard those too), and giving
// up after a bounded number of tries.
#pragma once

#include <functional>
#include <string>

#include "data/demonstrations.hpp"

namespace corrmp {

struct ExpertCollection {
  int train = 0;
  int validation = 0;
  int max_attempts = 0;  // scenarios tried at most
  std::string expert;    // named in messages
};

// `attempt()` draws a scenario and demonstrates it; it throws
// std::runtime_error (the reason) for a demonstration to drop. Throws when
// the sets cannot be filled within max_attempts, saying how many succeeded.
DemonstrationSplit collect_expert_demonstrations(const ExpertCollection& wanted,
                                                 const std::function<Demonstration()>& attempt);

}  // namespace corrmp
