// Comparison of groups of runs across seeds (run_comparison.hpp).
#include "report/run_comparison.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "report/comparison_groups.hpp"
#include "report/error_metrics.hpp"
#include "report/metric_ranges.hpp"
#include "report/report_text.hpp"
#include "stats/fisher_exact.hpp"

namespace corrmp {

namespace {

const std::string kSuccess = "task_success_rate";

// task_success_rate, decision_match_rate and every trajectory error the runs
// recorded (in the order the first run recording it did), then the extras.
std::vector<std::string> metric_columns(const std::vector<RunSummary>& runs,
                                        const std::vector<std::string>& extras) {
  std::vector<std::string> columns{kSuccess};
  auto add = [&](const std::string& name) {
    if (std::find(columns.begin(), columns.end(), name) == columns.end()) {
      columns.push_back(name);
    }
  };
  const auto recorded = [&](const std::string& name) {
    return std::any_of(runs.begin(), runs.end(),
                       [&](const RunSummary& run) { return run.metrics.count(name) > 0; });
  };
  if (recorded("decision_match_rate")) add("decision_match_rate");
  for (const auto& error : error_metrics(runs)) {
    add(error.mean);
    if (recorded(error.max)) add(error.max);
  }
  for (const auto& name : extras) add(name);
  return columns;
}

SuccessDifference success_difference(const RunGroup& group, const RunGroup& versus) {
  SuccessDifference d;
  d.group = group.name;
  d.versus = versus.name;
  d.group_pooled = group.pooled_success;
  d.versus_pooled = versus.pooled_success;
  d.pooled_difference = d.group_pooled.rate - d.versus_pooled.rate;
  const auto& g = d.group_pooled;
  const auto& v = d.versus_pooled;
  d.fisher_p = fisher_exact_two_sided(g.successes, g.trials - g.successes, v.successes,
                                      v.trials - v.successes);
  auto samples = [](const RunGroup& r) {
    const auto it = r.samples.find(kSuccess);
    return it == r.samples.end() ? std::vector<double>{} : it->second;
  };
  d.across_seeds = difference_interval(samples(versus), samples(group));
  return d;
}

// What the runs declared `metric` to be; nothing known when none recorded it.
MetricDeclaration declaration_of(const RunComparison& comparison, const std::string& metric) {
  const auto it = comparison.declarations.find(metric);
  return it == comparison.declarations.end() ? MetricDeclaration{} : it->second;
}

// The interval of a difference in task_success_rate, clipped to the differences of its range
// ([-1, 1]).
IntervalBounds difference_bounds(const RunComparison& comparison, const DifferenceInterval& d) {
  return clip_interval(d.low, d.high, difference_range(declaration_of(comparison, kSuccess).range));
}

std::string signed_number(double value) {
  if (std::isnan(value)) return "-";
  return (value >= 0 ? "+" : "") + report_number(value);
}

std::string difference_text(const RunComparison& comparison, const DifferenceInterval& d) {
  if (std::isnan(d.difference)) return "-";
  if (!d.defined()) return signed_number(d.difference) + " (a group has 1 run, no interval)";
  const IntervalBounds bounds = difference_bounds(comparison, d);
  return fmt::format("{} [{}, {}]", signed_number(d.difference), report_number(bounds.low),
                     report_number(bounds.high));
}

std::string pooled_short(const ProportionInterval& p) {
  if (p.trials == 0) return "no trials";
  return fmt::format("{} of {} ({:.1f}%)", p.successes, p.trials, 100 * p.rate);
}

std::string p_value_text(const SuccessDifference& d) {
  if (d.group_pooled.trials == 0 || d.versus_pooled.trials == 0) return "-";
  return fmt::format("{:.4g}", d.fisher_p);
}

}  // namespace

std::string group_name(const RunSummary& run, const std::vector<std::string>& group_by) {
  if (group_by.empty()) return run.experiment;
  std::string name;
  for (const auto& key : group_by) {
    const auto value = run_setting(run, key);
    name += fmt::format("{}{}={}", name.empty() ? "" : ", ", key, value ? *value : "(unset)");
  }
  return name;
}

RunComparison compare_runs(const std::vector<RunSummary>& runs, const ComparisonOptions& options) {
  if (runs.empty()) throw ComparisonError("no runs to compare");
  RunComparison comparison;
  comparison.grouping = "experiment";
  if (!options.group_by.empty()) {
    comparison.grouping.clear();
    for (const auto& key : options.group_by) {
      comparison.grouping += (comparison.grouping.empty() ? "" : ", ") + key;
    }
  }
  check_group_keys(runs, options.group_by);
  comparison.metrics = metric_columns(runs, options.extra_metrics);
  for (const auto& metric : comparison.metrics) {
    comparison.declarations[metric] = declared_metric(runs, metric);
  }

  std::vector<int> successes;
  std::vector<std::vector<const RunSummary*>> members;
  for (const auto& run : runs) {
    const std::string name = group_name(run, options.group_by);
    auto group = std::find_if(comparison.groups.begin(), comparison.groups.end(),
                              [&](const RunGroup& g) { return g.name == name; });
    if (group == comparison.groups.end()) {
      comparison.groups.push_back({name, {}, 0, {}, {}, {}, {}, {}});
      successes.push_back(0);
      members.emplace_back();
      group = comparison.groups.end() - 1;
    }
    group->runs.push_back(run.id);
    group->trials += run.trials;
    successes[group - comparison.groups.begin()] += run.successes;
    members[group - comparison.groups.begin()].push_back(&run);
    for (const auto& metric : comparison.metrics) {
      const auto value = run.metrics.find(metric);
      if (value != run.metrics.end()) group->samples[metric].push_back(value->second);
    }
  }
  for (size_t i = 0; i < comparison.groups.size(); ++i) {
    RunGroup& group = comparison.groups[i];
    group.pooled_success = wilson_interval(successes[i], group.trials);
    find_pooling(group, members[i], options.group_by);
    for (const auto& metric : comparison.metrics) {
      group.metrics[metric] = mean_interval(group.samples[metric]);
    }
  }

  const auto& groups = comparison.groups;
  if (!options.baseline.empty()) {
    const auto baseline = std::find_if(groups.begin(), groups.end(), [&](const RunGroup& g) {
      return g.name == options.baseline;
    });
    if (baseline == groups.end()) {
      std::string names;
      for (const auto& g : groups) names += (names.empty() ? "'" : ", '") + g.name + "'";
      throw ComparisonError(
          fmt::format("no group '{}' to compare with (the groups: {})", options.baseline, names));
    }
    for (const auto& group : groups) {
      if (&group != &*baseline) {
        comparison.differences.push_back(success_difference(group, *baseline));
      }
    }
  } else {
    for (size_t i = 0; i < groups.size(); ++i) {
      for (size_t j = i + 1; j < groups.size(); ++j) {
        comparison.differences.push_back(success_difference(groups[i], groups[j]));
      }
    }
  }
  return comparison;
}

std::vector<std::string> pooling_notes(const RunComparison& comparison) {
  std::vector<std::string> notes;
  for (const auto& group : comparison.groups) {
    std::vector<std::string> parts;
    if (group.experiments.size() > 1)
      parts.push_back(fmt::format("experiments {}", fmt::join(group.experiments, ", ")));
    if (!group.differing.empty()) {
      parts.push_back(fmt::format("runs that differ in {}", fmt::join(group.differing, ", ")));
    }
    if (parts.empty()) continue;
    notes.push_back(fmt::format("group {} pools {}", group.name,
                                parts.size() == 1 ? parts[0] : parts[0] + " and " + parts[1]));
  }
  return notes;
}

std::string comparison_markdown(const RunComparison& comparison) {
  size_t run_count = 0;
  for (const auto& group : comparison.groups) run_count += group.runs.size();
  std::string out = fmt::format(
      "# Comparison of runs\n\nGrouped by {}: {} groups, {} runs.\n\n"
      "Each metric: the mean across the group's runs (seeds) with its 95% confidence interval "
      "[low, high] (Student t, n - 1 degrees of freedom; with one run there is no interval), "
      "clipped to the values the metric can take: rates to [0, 1], errors, distances, times "
      "and counts at 0 (the mean is never clipped). A metric some runs did not record shows "
      "(n=...) runs. Pooled success: the trials of all the group's runs together, with a 95% "
      "Wilson interval.\n\n",
      comparison.grouping, comparison.groups.size(), run_count);
  const auto notes = pooling_notes(comparison);
  if (!notes.empty()) {
    out +=
        "**Groups pooling more than seeds:** their means, intervals and pooled trials "
        "average unlike runs as if they were seeds.\n\n";
    for (const auto& note : notes) out += "- " + markdown_cell(note) + "\n";
    out += "\n";
  }
  out += "| group | runs | trials | pooled task success |";
  std::string rule = "|---|---|---|---|";
  for (const auto& metric : comparison.metrics) {
    out += " " + markdown_cell(metric) + " |";
    rule += "---|";
  }
  out += "\n" + rule + "\n";
  for (const auto& group : comparison.groups) {
    out += fmt::format("| {} | {} | {} | {} |", markdown_cell(group.name), group.runs.size(),
                       group.trials, pooled_success_text(group.pooled_success));
    for (const auto& metric : comparison.metrics) {
      const MeanInterval& m = group.metrics.at(metric);
      const IntervalBounds bounds = metric_interval(declaration_of(comparison, metric), m);
      std::string cell = mean_with_interval(m, bounds.low, bounds.high);
      if (m.count > 0 && static_cast<size_t>(m.count) != group.runs.size()) {
        cell += fmt::format(" (n={})", m.count);
      }
      out += " " + cell + " |";
    }
    out += "\n";
  }
  out += "\nRuns:";
  for (const auto& group : comparison.groups) {
    std::string ids;
    for (int64_t id : group.runs) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    out += fmt::format(" {}: {}.", markdown_cell(group.name), ids);
  }
  out += "\n";

  if (comparison.differences.empty()) return out;
  out +=
      "\n## Differences in task success\n\n"
      "Test: Fisher's exact test, two-sided, on the 2x2 table of successes and failures with "
      "the trials pooled across each group's runs (seeds); pooling treats every trial as "
      "independent and ignores variation between seeds. Difference of means: the mean "
      "task_success_rate across seeds of the group minus that of the other, with a 95% Welch "
      "t interval clipped to [-1, 1].\n\n"
      "| group | versus | group pooled success | versus pooled success | pooled difference | "
      "Fisher p (two-sided, pooled trials) | difference of means across seeds [95% CI] |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const auto& d : comparison.differences) {
    out += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} |\n", markdown_cell(d.group), markdown_cell(d.versus),
        pooled_short(d.group_pooled), pooled_short(d.versus_pooled),
        std::isnan(d.pooled_difference) ? std::string("-")
                                        : fmt::format("{:+.1f} pp", 100 * d.pooled_difference),
        p_value_text(d), difference_text(comparison, d.across_seeds));
  }
  return out;
}

std::string comparison_csv(const RunComparison& comparison) {
  std::string out =
      "kind,group,versus,metric,runs,trials,successes,mean,ci_low,ci_high,versus_trials,"
      "versus_successes,fisher_p\n";
  for (const auto& group : comparison.groups) {
    const auto& p = group.pooled_success;
    out += fmt::format("pooled_success,{},,task_success,{},{},{},{},{},{},,,\n",
                       csv_cell(group.name), group.runs.size(), p.trials, p.successes,
                       csv_number(p.rate), csv_number(p.low), csv_number(p.high));
    for (const auto& metric : comparison.metrics) {
      const MeanInterval& m = group.metrics.at(metric);
      const IntervalBounds bounds = metric_interval(declaration_of(comparison, metric), m);
      out += fmt::format("mean,{},,{},{},{},,{},{},{},,,\n", csv_cell(group.name), csv_cell(metric),
                         m.count, group.trials, csv_number(m.mean), csv_number(bounds.low),
                         csv_number(bounds.high));
    }
  }
  for (const auto& d : comparison.differences) {
    const auto runs =
        std::find_if(comparison.groups.begin(), comparison.groups.end(), [&](const RunGroup& g) {
          return g.name == d.group;
        })->runs.size();
    out += fmt::format("difference,{},{},{},{},{},{},{},{},{},{},{},{}\n", csv_cell(d.group),
                       csv_cell(d.versus), kSuccess, runs, d.group_pooled.trials,
                       d.group_pooled.successes, csv_number(d.across_seeds.difference),
                       csv_number(difference_bounds(comparison, d.across_seeds).low),
                       csv_number(difference_bounds(comparison, d.across_seeds).high),
                       d.versus_pooled.trials, d.versus_pooled.successes,
                       d.group_pooled.trials == 0 || d.versus_pooled.trials == 0
                           ? std::string()
                           : csv_number(d.fisher_p));
  }
  return out;
}

}  // namespace corrmp
