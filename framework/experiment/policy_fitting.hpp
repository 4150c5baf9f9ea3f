// The training stage (paper, Section III): the context extractor learns from the
// demonstrations, their contexts are set, and the policy's networks learn. With two threads or
// more, the networks that read no context (the pre-MP's) do not wait for the extractor: one more
// thread trains them, one after another, on a copy of the demonstrations, while the extractor
// fits and then while the other networks train (docs/architecture.md, "Caches and determinism").
// Every network trains on the stream one fit of all would give it, so the models are the same
// whatever the number of threads. When the extractor fails, that thread's training is abandoned (at
// its next interrupt check) and the extractor's error is thrown.
#pragma once

#include <string>
#include <vector>

#include "context/context_extractor.hpp"
#include "core/seeds.hpp"
#include "data/demonstrations.hpp"
#include "policies/policy.hpp"

namespace corrmp {

struct PolicyFitting {
  Rng policy_rng;          // the policy's training stream
  Rng extractor_rng;       // the extractor's
  ExtractorCache cache;    // where the extractor may keep what it learned
  std::string output_dir;  // the run directory, for the extractor's figures
};

// Fits `extractor` (when not null) and writes the contexts into `demos`, then fits `policy`;
// returns the policy's training summaries in its segment order.
std::vector<PolicyTrainingSummary> fit_extractor_and_policy(Policy& policy,
                                                            ContextExtractor* extractor,
                                                            DemonstrationSplit& demos,
                                                            const PolicyFitting& fitting);

}  // namespace corrmp
