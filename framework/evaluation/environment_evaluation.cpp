// Closed-loop evaluation: runs the trials (environment_evaluation.hpp); the
// tables and metrics are made from them in evaluation_tables.cpp.
#include "evaluation/environment_evaluation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <mutex>

#include "core/interrupt.hpp"
#include "core/json_writer.hpp"
#include "core/progress.hpp"
#include "core/thread_budget.hpp"
#include "evaluation/evaluation_tables.hpp"
#include "evaluation/trajectory_error.hpp"

namespace corrmp {

namespace {

using SegmentPaths = std::map<std::string, Eigen::MatrixXd>;

// Thrown to a trial waiting for its extraction turn when an error left the task of an earlier
// trial: the loop may skip trials it had taken, whose turns would then never come.
struct EvaluationAbandoned : std::runtime_error {
  EvaluationAbandoned() : std::runtime_error("the evaluation stopped") {}
};

// Trials run concurrently, each in its own environment (Environment::clone), while the policy
// and the context extractor are shared: the policy generates one trajectory at a time, and the
// extractor, which may keep state from call to call (the colour segmentation's camera-noise
// stream and accuracy counts), extracts in trial order. Trial i makes its first extraction once
// trial i - 1 has made its last (or ended), so the extractor sees the calls a single thread
// would make, in the same order, and the results are the same whatever the thread count.
class SharedModels {
 public:
  SharedModels(Policy& policy, ContextExtractor* extractor, int trials)
      : policy_(policy),
        extractor_(extractor),
        extracted_(static_cast<size_t>(std::max(trials, 0)), false) {}

  CnmpPrediction generate(const std::string& segment, const Eigen::MatrixXd& start,
                          const Eigen::VectorXd& context, const Eigen::MatrixXd& query) {
    const std::lock_guard<std::mutex> lock(policy_mutex_);
    return policy_.generate(segment, start, context, query);
  }

  // Trial `trial`'s context of `segment`, after every extraction of the trials before it.
  Eigen::VectorXd extract(int trial, const std::string& segment, const Observation& observation) {
    std::unique_lock<std::mutex> lock(turn_mutex_);
    turn_changed_.wait(lock, [&] { return next_ == trial || trial > failed_; });
    if (next_ != trial) throw EvaluationAbandoned();
    return extractor_->extract(segment, observation);
  }

  // An error left trial `trial`'s task: the trials after it that wait for their turn throw
  // EvaluationAbandoned (never the error the loop reports, which is of a lower trial).
  void abandon_after(int trial) {
    {
      const std::lock_guard<std::mutex> lock(turn_mutex_);
      failed_ = std::min(failed_, trial);
    }
    turn_changed_.notify_all();
  }

  // Trial `trial` makes no further extraction: the next trial may start its own.
  void done_extracting(int trial) {
    {
      const std::lock_guard<std::mutex> lock(turn_mutex_);
      extracted_[static_cast<size_t>(trial)] = true;
      while (next_ < static_cast<int>(extracted_.size()) && extracted_[static_cast<size_t>(next_)])
        ++next_;
    }
    turn_changed_.notify_all();
  }

 private:
  Policy& policy_;
  ContextExtractor* extractor_;
  std::mutex policy_mutex_;
  std::mutex turn_mutex_;
  std::condition_variable turn_changed_;
  std::vector<bool> extracted_;                   // per trial: made its last extraction
  int next_ = 0;                                  // the lowest trial that may still extract
  int failed_ = std::numeric_limits<int>::max();  // the lowest trial an error left
};

// Marks a trial done extracting when it has made its last extraction, or when it ends.
class ExtractionTurn {
 public:
  ExtractionTurn(SharedModels& models, int trial) : models_(models), trial_(trial) {}
  ~ExtractionTurn() { done(); }
  ExtractionTurn(const ExtractionTurn&) = delete;
  ExtractionTurn& operator=(const ExtractionTurn&) = delete;
  void done() {
    if (!done_) models_.done_extracting(trial_);
    done_ = true;
  }

 private:
  SharedModels& models_;
  int trial_;
  bool done_ = false;
};

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
void split_at_reference_phases(SharedModels& models, const std::string& whole,
                               const TaskReport& task, const std::vector<SegmentInfo>& segments,
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
    Eigen::MatrixXd path = models.generate(whole, start, context, query).mean;
    if (s.relative) {
      out.origins[s.name] = path.row(0);
      for (int c : relative_columns_of(task, path.cols())) path.col(c).array() -= path(0, c);
    }
    out.generated[s.name] = path;
  }
}

// A whole-skill policy's executed path cut as split_at_reference_phases cuts
// what it generated: `executed` holds rows of the whole skill's uniform query
// over `points` rows; each segment's rows are interpolated at the segment's
// reference phases, as far as the execution got; a relative segment's are
// offsets from its generated origin.
void split_executed_at_reference_phases(const Eigen::MatrixXd& executed, int points,
                                        const TaskReport& task,
                                        const std::vector<SegmentInfo>& segments,
                                        const Demonstration& reference, EvaluatedTrial& out) {
  if (executed.rows() == 0 || points < 2) return;
  const double last = static_cast<double>(executed.rows() - 1);
  for (const auto& s : segments) {
    const SegmentTrajectory* demonstrated = reference.find(s.name);
    if (demonstrated == nullptr || !out.generated.count(s.name)) continue;
    const Eigen::VectorXd phases =
        Eigen::VectorXd::LinSpaced(s.points, demonstrated->phase_begin, demonstrated->phase_end);
    Eigen::MatrixXd path(s.points, executed.cols());
    Eigen::Index rows = 0;
    for (; rows < phases.size(); ++rows) {
      const double at = phases(rows) * (points - 1);
      if (!(at >= 0.0 && at <= last + 1e-9)) break;
      const Eigen::Index below =
          std::min(static_cast<Eigen::Index>(std::floor(at)), static_cast<Eigen::Index>(last));
      const Eigen::Index above = std::min(below + 1, static_cast<Eigen::Index>(last));
      const double fraction = std::min(at - static_cast<double>(below), 1.0);
      path.row(rows) = (1.0 - fraction) * executed.row(below) + fraction * executed.row(above);
    }
    if (rows == 0) continue;
    path.conservativeResize(rows, executed.cols());
    const auto origin = out.origins.find(s.name);
    if (s.relative && origin != out.origins.end()) {
      for (int c : relative_columns_of(task, path.cols())) path.col(c).array() -= origin->second(c);
    }
    out.executed[s.name] = path;
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

// What the trials share: the expert, the policy and extractor (SharedModels), what the task
// declares.
struct TrialSetting {
  DemonstrationSource& expert;
  SharedModels& models;
  std::vector<std::string> policy_segments;
  // Per policy segment: whether the extractor gives it a context (ContextExtractor::segments;
  // it is asked for no other).
  std::vector<bool> has_context;
  bool images = false;  // the extractor reads camera images
  TaskReport task;
};

TrialSetting trial_setting(DemonstrationSource& expert, SharedModels& models, const Policy& policy,
                           const ContextExtractor* extractor, const TaskReport& task) {
  TrialSetting setting{expert, models, policy.segments(), {}, false, task};
  const std::vector<std::string> listed =
      extractor != nullptr ? extractor->segments() : std::vector<std::string>{};
  for (const std::string& segment : setting.policy_segments)
    setting.has_context.push_back(std::find(listed.begin(), listed.end(), segment) != listed.end());
  setting.images = extractor != nullptr && extractor->needs_images();
  return setting;
}

// Runs one trial in `environment`: the expert's reference, then the policy segment by segment.
EvaluatedTrial run_trial(int index, const Scenario& scenario, Environment& environment,
                         const TrialSetting& setting, SegmentPaths& reference_paths) {
  ExtractionTurn turn(setting.models, index);
  const std::vector<SegmentInfo> env_segments = environment.segments();
  EvaluatedTrial trial;
  trial.trial = index;
  trial.scenario = scenario;
  Demonstration reference;
  try {
    reference = setting.expert.demonstrate(environment, scenario, false);
    trial.expected_action = reference.decision;
  } catch (const std::runtime_error& e) {
    spdlog::warn("trial {}: the expert failed on this scenario: {}", index, e.what());
  }
  for (const auto& s : reference.segments) reference_paths[s.segment] = s.y;

  environment.reset(scenario);
  std::string failure;
  const auto& has_context = setting.has_context;
  const size_t last_context = static_cast<size_t>(
      std::find(has_context.rbegin(), has_context.rend(), true).base() - has_context.begin());
  for (size_t k = 0; k < setting.policy_segments.size(); ++k) {
    const std::string& segment = setting.policy_segments[k];
    const Observation observation = environment.observe(setting.images);
    const Eigen::VectorXd context =
        has_context[k] ? setting.models.extract(index, segment, observation) : Eigen::VectorXd();
    if (k + 1 >= last_context) turn.done();
    if (context.size() > 0) trial.contexts[segment] = context;
    const SegmentInfo* info = find_segment(env_segments, segment);
    const Eigen::RowVectorXd start_row = environment.segment_start(segment);
    Eigen::MatrixXd start(1, 1 + start_row.size());
    start << 0.0, start_row;
    const int points = info != nullptr ? info->points : total_points(env_segments);
    const Eigen::MatrixXd query = Eigen::VectorXd::LinSpaced(points, 0.0, 1.0);
    const Eigen::MatrixXd path = setting.models.generate(segment, start, context, query).mean;
    if (info == nullptr) {
      split_at_reference_phases(setting.models, segment, setting.task, env_segments, reference,
                                start, context, trial);
    } else {
      trial.generated[segment] = path;
      if (info->relative) trial.origins[segment] = environment.effector_position();
    }
    failure = environment.execute(segment, path);
    const Eigen::MatrixXd executed = environment.executed_path();
    if (info == nullptr) {
      split_executed_at_reference_phases(executed, points, setting.task, env_segments, reference,
                                         trial);
    } else if (executed.rows() > 0) {
      trial.executed[segment] = executed;
    }
    if (!failure.empty()) break;
  }
  const Outcome outcome = environment.outcome();
  trial.success = failure.empty() && outcome.success;
  trial.failure = trial.success ? "" : (failure.empty() ? outcome.failure : failure);
  trial.outcome = outcome.metrics;
  trial.details = outcome.details;
  if (!setting.task.decision_labels.empty() &&
      trial.generated.count(setting.task.decision_segment)) {
    trial.chosen_action =
        environment.classify_decision(trial.generated[setting.task.decision_segment]);
  }
  return trial;
}

// A trial and the expert's paths it is compared with.
struct TrialRun {
  EvaluatedTrial trial;
  SegmentPaths reference;
};

}  // namespace

EnvironmentEvaluation evaluate_in_environment(Environment& environment, DemonstrationSource& expert,
                                              ContextExtractor* extractor, Policy& policy,
                                              int trials, Rng& rng, const std::string& label) {
  EnvironmentEvaluation result;
  result.task = environment.report();
  const TaskReport& task = result.task;
  // The scenarios are drawn in trial order, before any trial runs.
  std::vector<Scenario> scenarios;
  for (int index = 0; index < trials; ++index)
    scenarios.push_back(environment.sample_scenario(rng));

  SharedModels models(policy, extractor, trials);
  const TrialSetting setting = trial_setting(expert, models, policy, extractor, task);
  std::vector<TrialRun> runs(static_cast<size_t>(std::max(trials, 0)));
  EnvironmentCopies environments(environment, parallel_workers(trials));
  Progress progress("evaluation", trials);
  std::mutex progress_mutex;
  int finished = 0, successes = 0;
  parallel_for_with_workers(trials, environments.size(), [&](int index, int worker) {
    const Scenario& scenario = scenarios[static_cast<size_t>(index)];
    TrialRun& run = runs[static_cast<size_t>(index)];
    try {
      try {
        run.trial = run_trial(index, scenario, environments[worker], setting, run.reference);
      } catch (const Interrupted&) {
        throw;
      } catch (const EvaluationAbandoned&) {
        throw;
      } catch (const std::exception& e) {
        // One trial that cannot run is a failed trial with its reason, not a failed run.
        spdlog::warn("trial {} ({}): {}", index, scenario_json(scenario), e.what());
        run.trial = EvaluatedTrial{};
        run.trial.trial = index;
        run.trial.scenario = scenario;
        run.trial.failure = std::string("error: ") + e.what();
      }
      const std::lock_guard<std::mutex> lock(progress_mutex);
      successes += run.trial.success;
      ++finished;
      progress.advance(1, fmt::format("{} of {} succeeded", successes, finished));
    } catch (...) {
      models.abandon_after(index);
      throw;
    }
  });
  progress.finish(fmt::format("{} of {} succeeded", successes, trials));

  std::map<std::string, TrajectoryErrorAccumulator> errors;
  for (TrialRun& run : runs) {
    EvaluatedTrial& trial = run.trial;
    // Only segments the expert also showed, at the same resolution, are kept.
    for (auto it = trial.generated.begin(); it != trial.generated.end();) {
      const auto demonstrated = run.reference.find(it->first);
      if (demonstrated == run.reference.end() || demonstrated->second.rows() != it->second.rows()) {
        trial.executed.erase(it->first);
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
    result.trials.push_back(TrialRecord{trial.trial, scenario_json(trial.scenario),
                                        trial.expected_action, trial.chosen_action, trial.success,
                                        trial.failure, details_json(trial)});
    result.evaluated.push_back(std::move(trial));
  }

  std::map<std::string, TrajectoryError> segment_errors;
  for (const auto& [segment, accumulator] : errors) segment_errors[segment] = accumulator.result();
  // The policy decides when it generates the decision segment, or the whole skill.
  const std::vector<SegmentInfo> env_segments = environment.segments();
  const std::vector<std::string>& segments = setting.policy_segments;
  const bool decides =
      !task.decision_labels.empty() &&
      std::any_of(segments.begin(), segments.end(), [&](const std::string& s) {
        return s == task.decision_segment || find_segment(env_segments, s) == nullptr;
      });
  result.metrics = evaluation_metrics(task, decides, result.evaluated, segment_errors);
  result.tables = evaluation_tables(task, decides, result.evaluated, segment_errors, label);
  const Environment::RunAdditions added = environment.run_additions(result.evaluated, label);
  result.metrics.insert(result.metrics.end(), added.metrics.begin(), added.metrics.end());
  if (!added.log.empty()) spdlog::info("{}", added.log);
  return result;
}

}  // namespace corrmp
