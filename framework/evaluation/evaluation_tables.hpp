// The run metrics and the printed tables of a closed-loop evaluation, made
// from what the task declares (TaskReport): the decision table (the paper's
// Table I: action choice, decision match and task success per expected
// decision), the trajectory errors of the error segments (Table II, mean and
// max in the task's unit) and the rates of the task's outcome metrics, with
// the trials' failures counted by reason.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "data/evaluated_trial.hpp"
#include "envs/environment.hpp"
#include "evaluation/trajectory_error.hpp"
#include "store/records.hpp"

namespace corrmp {

// task_success_rate; with decision labels, per label L expected at least
// once, expected_L and task_success_rate_L, and when the policy decides,
// decision_match_rate and decision_match_rate_L; <segment>_mp_error_mean_<unit> and ..._max_<unit>;
// <metric>_rate for each outcome metric (its mean over the trials);
// failures_<category> (spaces as '_') for each failure category. Each is declared
// (core/metric.hpp): the rates in [0, 1], success and decision match higher is
// better; the errors at least 0 in the task's error unit, lower is better, their
// mean and max under the heading "<segment>-MP error mean / max (<unit>)"; the
// counts at least 0, failures lower is better.
// `decided`: whether the policy makes the task's decision at all (one
// without the decision segment, such as pre-MP then post-MP, does not: its
// decision match is not reported).
std::vector<MetricRecord> evaluation_metrics(const TaskReport& task, bool decided,
                                             const std::vector<EvaluatedTrial>& trials,
                                             const std::map<std::string, TrajectoryError>& errors);

std::string evaluation_tables(const TaskReport& task, bool decided,
                              const std::vector<EvaluatedTrial>& trials,
                              const std::map<std::string, TrajectoryError>& errors,
                              const std::string& label);

}  // namespace corrmp
