// Closed-loop evaluation and the paper's tables.
#include "experiment/environment_evaluation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "cnmp/cnmp_trainer.hpp"
#include "core/interrupt.hpp"
#include "core/progress.hpp"

namespace corrmp {

namespace {

const std::vector<std::string> kCorrections{"push", "none", "pull"};

// Generated trajectories of one trial, per environment segment.
using SegmentPaths = std::map<std::string, Eigen::MatrixXd>;

// A whole-skill policy's segments, for the errors and the decision: it is
// queried over each segment's span in the reference demonstration's timing,
// between the critical points the expert passed at its nominal tempo. What
// is executed is the policy's own uniform query; this only reads it.
void split_at_reference_phases(Policy& policy, const std::string& whole,
                               const std::vector<SegmentInfo>& segments,
                               const Demonstration& reference, const Eigen::MatrixXd& start,
                               const Eigen::VectorXd& context, SegmentPaths& out) {
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
    out[s.name] = policy.generate(whole, start, context, query).mean;
  }
}

int points_of(const std::vector<SegmentInfo>& segments, const std::string& name) {
  int total = 0;
  for (const auto& s : segments) {
    if (s.name == name) return s.points;
    total += s.points;
  }
  return total;  // a whole-trajectory segment spans them all
}

std::string percent(int part, int whole) {
  return whole > 0 ? fmt::format("{:.0f}%", 100.0 * part / whole) : "-";
}

}  // namespace

EnvironmentEvaluation evaluate_in_environment(Environment& environment, DemonstrationSource& expert,
                                              ContextExtractor* extractor, Policy& policy,
                                              int trials, Rng& rng, const std::string& label) {
  EnvironmentEvaluation result;
  const std::vector<SegmentInfo> env_segments = environment.segments();
  const bool images = extractor != nullptr && extractor->needs_images();
  std::map<std::string, TrajectoryErrorAccumulator> errors;
  std::map<std::string, std::map<std::string, int>> choices;  // expected -> chosen -> count
  std::map<std::string, int> expected_count, matched, succeeded;
  Progress progress("evaluation", trials);
  int successes = 0, matches = 0;
  for (int trial = 0; trial < trials; ++trial) {
    check_interrupt();
    const Scenario scenario = environment.sample_scenario(rng);
    TrialRecord record;
    record.trial = trial;
    record.scenario = scenario_json(scenario);
    Demonstration reference;
    try {
      reference = expert.demonstrate(environment, scenario, false);
      record.expected_action = reference.correction;
    } catch (const std::runtime_error& e) {
      spdlog::warn("trial {}: the expert failed on this scenario: {}", trial, e.what());
    }

    environment.reset(scenario);
    SegmentPaths trajectories;
    std::string failure;
    for (const std::string& segment : policy.segments()) {
      const Observation observation = environment.observe(images);
      const Eigen::VectorXd context =
          extractor != nullptr ? extractor->extract(segment, observation) : Eigen::VectorXd();
      const Eigen::RowVectorXd start_y = environment.effector_position();
      Eigen::MatrixXd start(1, 1 + start_y.size());
      start << 0.0, start_y;
      const Eigen::MatrixXd query =
          Eigen::VectorXd::LinSpaced(points_of(env_segments, segment), 0.0, 1.0);
      const Eigen::MatrixXd path = policy.generate(segment, start, context, query).mean;
      const bool whole_skill =
          std::none_of(env_segments.begin(), env_segments.end(),
                       [&](const SegmentInfo& s) { return s.name == segment; });
      if (whole_skill) {
        split_at_reference_phases(policy, segment, env_segments, reference, start, context,
                                  trajectories);
      } else {
        trajectories[segment] = path;
      }
      failure = environment.execute(path);
      if (!failure.empty()) break;
    }
    const Outcome outcome = environment.outcome();
    record.success = failure.empty() && outcome.success;
    record.failure = failure.empty() ? outcome.failure : failure;
    if (trajectories.count("cor")) {
      record.chosen_action = environment.classify_correction(trajectories["cor"]);
    }
    TrialTrajectories paths{trial, record.success, record.expected_action, record.chosen_action, {},
                            {}};
    for (const auto& [segment, path] : trajectories) {
      const SegmentTrajectory* demonstrated = reference.find(segment);
      if (demonstrated == nullptr || demonstrated->y.rows() != path.rows()) continue;
      errors[segment].add(100.0 * mean_row_distance(path, demonstrated->y));
      paths.generated[segment] = path;
      paths.expert[segment] = demonstrated->y;
    }
    result.trajectories.push_back(std::move(paths));
    successes += record.success;
    const bool match =
        !record.expected_action.empty() && record.expected_action == record.chosen_action;
    matches += match;
    if (!record.expected_action.empty()) {
      ++expected_count[record.expected_action];
      ++choices[record.expected_action][record.chosen_action.empty() ? "?" : record.chosen_action];
      matched[record.expected_action] += match;
      succeeded[record.expected_action] += record.success;
    }
    result.trials.push_back(record);
    progress.advance(1, fmt::format("{} of {} succeeded", successes, trial + 1));
  }
  progress.finish(fmt::format("{} of {} succeeded", successes, trials));

  auto& m = result.metrics;
  m.push_back({"task_success_rate", static_cast<double>(successes) / trials});
  m.push_back({"decision_match_rate", static_cast<double>(matches) / trials});
  for (const auto& [segment, name] :
       std::vector<std::pair<std::string, std::string>>{{"cor", "cor_mp"}, {"post", "post_mp"}}) {
    if (!errors.count(segment)) continue;
    m.push_back({name + "_error_mean_cm", errors[segment].result().mean});
    m.push_back({name + "_error_max_cm", errors[segment].result().max});
  }
  for (const auto& c : kCorrections) {
    if (expected_count[c] == 0) continue;
    m.push_back({"expected_" + c, static_cast<double>(expected_count[c])});
    m.push_back({"decision_match_rate_" + c, static_cast<double>(matched[c]) / expected_count[c]});
    m.push_back({"task_success_rate_" + c, static_cast<double>(succeeded[c]) / expected_count[c]});
  }

  std::string& t = result.tables;
  t += fmt::format("Table I ({}): {} of {} trials succeeded, decision match {}\n", label, successes,
                   trials, percent(matches, trials));
  t += fmt::format("  {:<14} {:<34} {:>15} {:>13}\n", "expected", "action choice", "decision match",
                   "task success");
  for (const auto& c : kCorrections) {
    if (expected_count[c] == 0) continue;
    std::string chosen;
    for (const auto& [action, count] : choices[c]) {
      chosen += fmt::format("{}{} {}", chosen.empty() ? "" : ", ", count, action);
    }
    t += fmt::format("  {:<14} {:<34} {:>15} {:>13}\n", c, chosen,
                     percent(matched[c], expected_count[c]),
                     percent(succeeded[c], expected_count[c]));
  }
  t += fmt::format("Table II ({}): prediction errors (cm)\n", label);
  t += fmt::format("  {:<10} {:>8} {:>8}\n", "", "mean", "max");
  for (const auto& [segment, name] :
       std::vector<std::pair<std::string, std::string>>{{"cor", "cor-MP"}, {"post", "post-MP"}}) {
    if (!errors.count(segment)) continue;
    const TrajectoryError e = errors[segment].result();
    t += fmt::format("  {:<10} {:>8.2f} {:>8.2f}\n", name, e.mean, e.max);
  }
  return result;
}

}  // namespace corrmp
