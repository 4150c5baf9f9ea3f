// Closed-loop evaluation: runs the trials (environment_evaluation.hpp); the
// tables and metrics are made from them in evaluation_tables.cpp.
#include "experiment/environment_evaluation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "core/interrupt.hpp"
#include "core/json_writer.hpp"
#include "core/progress.hpp"
#include "experiment/evaluation_tables.hpp"

namespace corrmp {

namespace {

using SegmentPaths = std::map<std::string, Eigen::MatrixXd>;

const SegmentInfo* find_segment(const std::vector<SegmentInfo>& segments, const std::string& name) {
  for (const auto& s : segments) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

int total_points(const std::vector<SegmentInfo>& segments) {
  int total = 0;
  for (const auto& s : segments) total += s.points;
  return total;
}

// A whole-skill policy's segments, for the errors and the decision: it is
// queried over each segment's span in the reference demonstration's timing,
// between the critical points the expert passed at its nominal tempo. What
// is executed is the policy's own uniform query; this only reads it.
// A relative segment is read as offsets from where the policy's span starts.
void split_at_reference_phases(Policy& policy, const std::string& whole, const TaskReport& task,
                               const std::vector<SegmentInfo>& segments,
                               const Demonstration& reference, const Eigen::MatrixXd& start,
                               const Eigen::VectorXd& context, EvaluatedTrial& out) {
  for (const auto& s : segments) {
    const SegmentTrajectory* demonstrated = reference.find(s.name);
    if (demonstrated == nullptr) continue;
    if (!std::isfinite(demonstrated->phase_begin) || !std::isfinite(demonstrated->phase_end)) {
      throw std::runtime_error(fmt::format(
          "the reference demonstration's segment '{}' has no span in the whole skill, so the "
          "whole-skill policy '{}' cannot be cut into segments",
          s.name, whole));
    }
    const Eigen::MatrixXd query =
        Eigen::VectorXd::LinSpaced(s.points, demonstrated->phase_begin, demonstrated->phase_end);
    Eigen::MatrixXd path = policy.generate(whole, start, context, query).mean;
    if (s.relative) {
      out.origins[s.name] = path.row(0);
      for (int c : relative_columns_of(task, path.cols())) path.col(c).array() -= path(0, c);
    }
    out.generated[s.name] = path;
  }
}

Eigen::MatrixXd error_columns_of(const Eigen::MatrixXd& path, const std::vector<int>& columns) {
  if (columns.empty()) return path;
  Eigen::MatrixXd out(path.rows(), static_cast<Eigen::Index>(columns.size()));
  for (size_t i = 0; i < columns.size(); ++i) out.col(i) = path.col(columns[i]);
  return out;
}

std::string details_json(const EvaluatedTrial& trial) {
  JsonObject contexts, outcome, values;
  for (const auto& [segment, context] : trial.contexts) {
    contexts.add(segment, std::vector<double>(context.data(), context.data() + context.size()));
  }
  for (const auto& [name, value] : trial.outcome) outcome.add(name, value);
  for (const auto& [name, value] : trial.details) values.add(name, value);
  JsonObject details;
  details.add("contexts", contexts).add("outcome", outcome).add("values", values);
  return details.str();
}

// Runs one trial: the expert's reference, then the policy segment by segment.
EvaluatedTrial run_trial(int index, const Scenario& scenario, Environment& environment,
                         DemonstrationSource& expert, ContextExtractor* extractor, Policy& policy,
                         const TaskReport& task, SegmentPaths& reference_paths) {
  const std::vector<SegmentInfo> env_segments = environment.segments();
  const bool images = extractor != nullptr && extractor->needs_images();
  EvaluatedTrial trial;
  trial.trial = index;
  trial.scenario = scenario;
  Demonstration reference;
  try {
    reference = expert.demonstrate(environment, scenario, false);
    trial.expected_action = reference.decision;
  } catch (const std::runtime_error& e) {
    spdlog::warn("trial {}: the expert failed on this scenario: {}", index, e.what());
  }
  for (const auto& s : reference.segments) reference_paths[s.segment] = s.y;

  environment.reset(scenario);
  std::string failure;
  for (const std::string& segment : policy.segments()) {
    const Observation observation = environment.observe(images);
    const Eigen::VectorXd context =
        extractor != nullptr ? extractor->extract(segment, observation) : Eigen::VectorXd();
    if (context.size() > 0) trial.contexts[segment] = context;
    const SegmentInfo* info = find_segment(env_segments, segment);
    const Eigen::RowVectorXd start_row = environment.segment_start(segment);
    Eigen::MatrixXd start(1, 1 + start_row.size());
    start << 0.0, start_row;
    const int points = info != nullptr ? info->points : total_points(env_segments);
    const Eigen::MatrixXd query = Eigen::VectorXd::LinSpaced(points, 0.0, 1.0);
    const Eigen::MatrixXd path = policy.generate(segment, start, context, query).mean;
    if (info == nullptr) {
      split_at_reference_phases(policy, segment, task, env_segments, reference, start, context,
                                trial);
    } else {
      trial.generated[segment] = path;
      if (info->relative) trial.origins[segment] = environment.effector_position();
    }
    failure = environment.execute(segment, path);
    if (!failure.empty()) break;
  }
  const Outcome outcome = environment.outcome();
  trial.success = failure.empty() && outcome.success;
  trial.failure = trial.success ? "" : (failure.empty() ? outcome.failure : failure);
  trial.outcome = outcome.metrics;
  trial.details = outcome.details;
  if (!task.decision_labels.empty() && trial.generated.count(task.decision_segment)) {
    trial.chosen_action = environment.classify_decision(trial.generated[task.decision_segment]);
  }
  return trial;
}

}  // namespace

EnvironmentEvaluation evaluate_in_environment(Environment& environment, DemonstrationSource& expert,
                                              ContextExtractor* extractor, Policy& policy,
                                              int trials, Rng& rng, const std::string& label) {
  EnvironmentEvaluation result;
  result.task = environment.report();
  const TaskReport& task = result.task;
  std::map<std::string, TrajectoryErrorAccumulator> errors;
  Progress progress("evaluation", trials);
  int successes = 0;
  for (int index = 0; index < trials; ++index) {
    check_interrupt();
    const Scenario scenario = environment.sample_scenario(rng);
    SegmentPaths reference;
    EvaluatedTrial trial;
    try {
      trial = run_trial(index, scenario, environment, expert, extractor, policy, task, reference);
    } catch (const Interrupted&) {
      throw;
    } catch (const std::exception& e) {
      // One trial that cannot run is a failed trial with its reason, not a failed run.
      spdlog::warn("trial {} ({}): {}", index, scenario_json(scenario), e.what());
      trial = EvaluatedTrial{};
      trial.trial = index;
      trial.scenario = scenario;
      trial.failure = std::string("error: ") + e.what();
    }
    // Only segments the expert also showed, at the same resolution, are kept.
    for (auto it = trial.generated.begin(); it != trial.generated.end();) {
      const auto demonstrated = reference.find(it->first);
      if (demonstrated == reference.end() || demonstrated->second.rows() != it->second.rows()) {
        it = trial.generated.erase(it);
        continue;
      }
      trial.expert[it->first] = demonstrated->second;
      if (std::count(task.error_segments.begin(), task.error_segments.end(), it->first)) {
        errors[it->first].add(
            task.error_scale *
            mean_row_distance(error_columns_of(it->second, task.error_columns),
                              error_columns_of(demonstrated->second, task.error_columns)));
      }
      ++it;
    }
    result.trials.push_back(TrialRecord{index, scenario_json(scenario), trial.expected_action,
                                        trial.chosen_action, trial.success, trial.failure,
                                        details_json(trial)});
    successes += trial.success;
    result.evaluated.push_back(std::move(trial));
    progress.advance(1, fmt::format("{} of {} succeeded", successes, index + 1));
  }
  progress.finish(fmt::format("{} of {} succeeded", successes, trials));

  std::map<std::string, TrajectoryError> segment_errors;
  for (const auto& [segment, accumulator] : errors) segment_errors[segment] = accumulator.result();
  // The policy decides when it generates the decision segment, or the whole skill.
  const std::vector<SegmentInfo> env_segments = environment.segments();
  const auto segments = policy.segments();
  const bool decides =
      !task.decision_labels.empty() &&
      std::any_of(segments.begin(), segments.end(), [&](const std::string& s) {
        return s == task.decision_segment || find_segment(env_segments, s) == nullptr;
      });
  result.metrics = evaluation_metrics(task, decides, result.evaluated, segment_errors);
  result.tables = evaluation_tables(task, decides, result.evaluated, segment_errors, label);
  return result;
}

}  // namespace corrmp
