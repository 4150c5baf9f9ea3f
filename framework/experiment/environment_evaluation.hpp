// Closed-loop evaluation in the environment (paper, Section IV-B): for each
// trial a scenario is drawn from the evaluation's own seed stream, the expert
// shows what it would do (the expected correction and reference trajectories),
// and the policy executes segment after segment, each generated from the
// effector's position and the context observed at the segment's start.
// Measures the paper's Table I (action choice, decision match, task success
// per expected correction) and Table II (cor-MP and post-MP errors in cm).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "context/context_extractor.hpp"
#include "envs/demonstrations.hpp"
#include "envs/environment.hpp"
#include "policies/policy.hpp"
#include "store/result_store.hpp"

namespace corrmp {

// One trial's generated and expert trajectories (rows x, y, z), per segment.
struct TrialTrajectories {
  int trial = 0;
  bool success = false;
  std::string expected_action, chosen_action;
  std::map<std::string, Eigen::MatrixXd> generated, expert;
};

struct EnvironmentEvaluation {
  std::vector<TrialRecord> trials;
  std::vector<TrialTrajectories> trajectories;
  std::vector<MetricRecord> metrics;
  std::string tables;  // Table I and Table II rows, as text
};

EnvironmentEvaluation evaluate_in_environment(Environment& environment, DemonstrationSource& expert,
                                              ContextExtractor* extractor, Policy& policy,
                                              int trials, Rng& rng, const std::string& label);

}  // namespace corrmp
