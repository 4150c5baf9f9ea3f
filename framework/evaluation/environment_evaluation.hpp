// Closed-loop evaluation in the environment (paper, Section IV-B): for each
// trial a scenario is drawn from the evaluation's own seed stream, the expert
// shows what it would do (the expected decision and reference trajectories),
// and the policy executes segment after segment, each generated from the
// effectors' position (or, for a relative segment, from zero offset) and the
// context observed at the segment's start. What is measured is what the task
// declares (TaskReport): the decision table (the paper's Table I), the
// trajectory errors of its error segments (Table II) and its outcome metrics,
// then what the task adds (Environment::run_additions).
//
// The trials run in parallel (core/thread_budget.hpp), each in its own environment
// (Environment::clone; one after another where the task cannot clone), with the results a single
// thread gives: the scenarios are drawn in trial order first, the policy generates one
// trajectory at a time, the context extractor sees its calls in trial order, and the records
// come in trial order. The expert demonstrates in several environments at once, as when it
// collects.
#pragma once

#include <string>
#include <vector>

#include "context/context_extractor.hpp"
#include "data/evaluated_trial.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/environment.hpp"
#include "policies/policy.hpp"
#include "store/records.hpp"

namespace corrmp {

struct EnvironmentEvaluation {
  TaskReport task;
  std::vector<TrialRecord> trials;
  std::vector<EvaluatedTrial> evaluated;
  std::vector<MetricRecord> metrics;
  std::string tables;  // the decision, error and outcome tables, as text
};

EnvironmentEvaluation evaluate_in_environment(Environment& environment, DemonstrationSource& expert,
                                              ContextExtractor* extractor, Policy& policy,
                                              int trials, Rng& rng, const std::string& label);

}  // namespace corrmp
