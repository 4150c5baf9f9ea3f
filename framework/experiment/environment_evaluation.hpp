// Closed-loop evaluation in the environment (paper, Section IV-B): for each
// trial a scenario is drawn from the evaluation's own seed stream, the expert
// shows what it would do (the expected correction and reference trajectories),
// and the policy executes segment after segment, each generated from the
// effector's position and the context observed at the segment's start.
// Measures the paper's Table I (action choice, decision match, task success
// per expected correction) and Table II (cor-MP and post-MP errors in cm).
#pragma once

#include <string>
#include <vector>

#include "context/context_extractor.hpp"
#include "envs/demonstrations.hpp"
#include "envs/environment.hpp"
#include "policies/policy.hpp"
#include "store/result_store.hpp"

namespace corrmp {

struct EnvironmentEvaluation {
  std::vector<TrialRecord> trials;
  std::vector<MetricRecord> metrics;
  std::string tables;  // Table I and Table II rows, as text
};

// `trajectory_csv`: when not empty, every generated and expert trajectory is
// written there (trial, segment, step, generated x/y/z, expert x/y/z).
EnvironmentEvaluation evaluate_in_environment(Environment& environment, DemonstrationSource& expert,
                                              ContextExtractor* extractor, Policy& policy,
                                              int trials, Rng& rng, const std::string& label,
                                              const std::string& trajectory_csv);

}  // namespace corrmp
