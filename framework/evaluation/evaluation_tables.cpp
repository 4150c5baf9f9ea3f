// Metrics and tables of a closed-loop evaluation (evaluation_tables.hpp).
#include "evaluation/evaluation_tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

namespace corrmp {

namespace {

// Counts per expected decision label.
struct DecisionCounts {
  int expected = 0, matched = 0, succeeded = 0;
  std::map<std::string, int> chosen;
};

std::map<std::string, DecisionCounts> count_decisions(const std::vector<EvaluatedTrial>& trials) {
  std::map<std::string, DecisionCounts> counts;
  for (const auto& trial : trials) {
    if (trial.expected_action.empty()) continue;
    DecisionCounts& c = counts[trial.expected_action];
    ++c.expected;
    c.matched += trial.expected_action == trial.chosen_action;
    c.succeeded += trial.success;
    ++c.chosen[trial.chosen_action.empty() ? "?" : trial.chosen_action];
  }
  return counts;
}

int count_successes(const std::vector<EvaluatedTrial>& trials) {
  return static_cast<int>(std::count_if(trials.begin(), trials.end(),
                                        [](const EvaluatedTrial& t) { return t.success; }));
}

int count_matches(const std::vector<EvaluatedTrial>& trials) {
  return static_cast<int>(std::count_if(trials.begin(), trials.end(), [](const EvaluatedTrial& t) {
    return !t.expected_action.empty() && t.expected_action == t.chosen_action;
  }));
}

double outcome_mean(const std::vector<EvaluatedTrial>& trials, const std::string& name) {
  double sum = 0.0;
  for (const auto& trial : trials) {
    const auto it = trial.outcome.find(name);
    if (it != trial.outcome.end()) sum += it->second;
  }
  return trials.empty() ? 0.0 : sum / static_cast<double>(trials.size());
}

// Failed trials whose reason starts with `category`.
int count_failures(const std::vector<EvaluatedTrial>& trials, const std::string& category) {
  return static_cast<int>(std::count_if(trials.begin(), trials.end(), [&](const EvaluatedTrial& t) {
    return !t.success && in_failure_category(t.failure, category);
  }));
}

// The width of a table's first column: its longest name, at least `minimum`.
size_t column_width(const std::vector<std::string>& names, size_t minimum) {
  size_t width = minimum;
  for (const auto& name : names) width = std::max(width, name.size());
  return width;
}

std::string percent(int part, int whole) {
  return whole > 0 ? fmt::format("{:.0f}%", 100.0 * part / whole) : "-";
}

std::string metric_segment(const std::string& segment) { return segment + "_mp"; }

}  // namespace

std::vector<MetricRecord> evaluation_metrics(const TaskReport& task, bool decided,
                                             const std::vector<EvaluatedTrial>& trials,
                                             const std::map<std::string, TrajectoryError>& errors) {
  const MetricDeclaration success = rate_metric(Better::higher);
  const MetricDeclaration count = count_metric(Better::neither);
  std::vector<MetricRecord> m;
  const double n = std::max<double>(1.0, static_cast<double>(trials.size()));
  m.push_back({"task_success_rate", count_successes(trials) / n, success});
  if (decided) m.push_back({"decision_match_rate", count_matches(trials) / n, success});
  for (const auto& segment : task.error_segments) {
    const auto it = errors.find(segment);
    if (it == errors.end()) continue;
    const std::string heading =
        fmt::format("{}-MP error mean / max ({})", segment, task.error_unit);
    m.push_back({fmt::format("{}_error_mean_{}", metric_segment(segment), task.error_unit),
                 it->second.mean, error_statistic(task.error_unit, heading, "mean")});
    m.push_back({fmt::format("{}_error_max_{}", metric_segment(segment), task.error_unit),
                 it->second.max, error_statistic(task.error_unit, heading, "max")});
  }
  const auto decisions = count_decisions(trials);
  for (const auto& label : task.decision_labels) {
    const auto it = decisions.find(label);
    if (it == decisions.end()) continue;
    const DecisionCounts& c = it->second;
    m.push_back({"expected_" + label, static_cast<double>(c.expected), count});
    if (decided) {
      m.push_back(
          {"decision_match_rate_" + label, static_cast<double>(c.matched) / c.expected, success});
    }
    m.push_back(
        {"task_success_rate_" + label, static_cast<double>(c.succeeded) / c.expected, success});
  }
  for (const auto& name : task.outcome_metrics) {
    m.push_back({name + "_rate", outcome_mean(trials, name), rate_metric(Better::neither)});
  }
  for (const auto& category : task.failure_categories) {
    m.push_back({failure_count_metric(category),
                 static_cast<double>(count_failures(trials, category)),
                 count_metric(Better::lower)});
  }
  return m;
}

std::string evaluation_tables(const TaskReport& task, bool decided,
                              const std::vector<EvaluatedTrial>& trials,
                              const std::map<std::string, TrajectoryError>& errors,
                              const std::string& label) {
  const int count = static_cast<int>(trials.size());
  const int successes = count_successes(trials);
  std::string t;
  if (!task.decision_labels.empty()) {
    t += fmt::format("Table I ({}): {} of {} trials succeeded, decision match {}\n", label,
                     successes, count, decided ? percent(count_matches(trials), count) : "-");
    const size_t w = column_width(task.decision_labels, 14);
    const auto decisions = count_decisions(trials);
    std::map<std::string, std::string> choices;  // per expected decision, "1 push, 2 none"
    size_t choice_width = 34;  // wide enough for the corridor's; the rope's may need more
    for (const auto& [name, tally] : decisions) {
      std::string chosen;
      for (const auto& [action, n] : tally.chosen) {
        chosen += fmt::format("{}{} {}", chosen.empty() ? "" : ", ", n, action);
      }
      choice_width = std::max(choice_width, chosen.size());
      choices[name] = chosen;
    }
    t += fmt::format("  {:<{}} {:<{}} {:>15} {:>13}\n", "expected", w, "action choice",
                     choice_width, "decision match", "task success");
    for (const auto& name : task.decision_labels) {
      const auto it = decisions.find(name);
      if (it == decisions.end()) continue;
      t += fmt::format("  {:<{}} {:<{}} {:>15} {:>13}\n", name, w, decided ? choices[name] : "-",
                       choice_width,
                       decided ? percent(it->second.matched, it->second.expected) : "-",
                       percent(it->second.succeeded, it->second.expected));
    }
  } else {
    t += fmt::format("Task success ({}): {} of {} trials succeeded\n", label, successes, count);
  }
  if (!errors.empty()) {
    t += fmt::format("Table II ({}): prediction errors ({})\n", label, task.error_unit);
    t += fmt::format("  {:<10} {:>8} {:>8}\n", "", "mean", "max");
    for (const auto& segment : task.error_segments) {
      const auto it = errors.find(segment);
      if (it == errors.end()) continue;
      t += fmt::format("  {:<10} {:>8.2f} {:>8.2f}\n", segment + "-MP", it->second.mean,
                       it->second.max);
    }
  }
  if (!task.outcome_metrics.empty()) {
    t += fmt::format("Outcomes ({}):\n", label);
    for (const auto& name : task.outcome_metrics) {
      t += fmt::format("  {:<{}} {:>6.0f}%\n", name, column_width(task.outcome_metrics, 24),
                       100.0 * outcome_mean(trials, name));
    }
  }
  if (!task.failure_categories.empty() && successes < count) {
    t += fmt::format("Failures ({}): {} of {} trials, by category (share of all trials)\n", label,
                     count - successes, count);
    const size_t w = column_width(task.failure_categories, 24);
    int categorised = 0;
    for (const auto& category : task.failure_categories) {
      const int n = count_failures(trials, category);
      categorised += n;
      t += fmt::format("  {:<{}} {:>3} {:>5}\n", category, w, n, percent(n, count));
    }
    const int other = std::max(0, count - successes - categorised);
    if (other > 0)
      t += fmt::format("  {:<{}} {:>3} {:>5}\n", "other", w, other, percent(other, count));
  }
  return t;
}

}  // namespace corrmp
