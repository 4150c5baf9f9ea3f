// Comparison of groups of recorded runs (results across seeds): runs
// grouped by experiment or by setting values (a sweep's axes), each group's
// main metrics as the mean across its runs (seeds) with a 95% Student t
// interval and its pooled task success with a Wilson interval, then the
// difference in task success between groups: Fisher's exact test on the
// trials pooled across seeds, and the difference of means across seeds with
// Welch's interval. Printed as Markdown or CSV with every interval clipped to
// the values its metric can take (its declared range, metric_ranges.hpp). A group that pools more
// than seeds (several experiments, or runs that differ in a setting other than a seed) is named in
// the comparison's notes.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/run_summaries.hpp"
#include "stats/mean_interval.hpp"
#include "stats/wilson_interval.hpp"

namespace corrmp {

// A comparison that cannot be made as asked (no runs, a group_by key no run
// has, an unknown baseline).
class ComparisonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ComparisonOptions {
  // Setting keys whose values make the groups (run_setting: sweep axes, then
  // the resolved config); empty: by experiment.
  std::vector<std::string> group_by;
  std::vector<std::string> extra_metrics;  // more metrics, by name
  std::string baseline;                    // a group compared with every other; empty: every pair
};

struct RunGroup {
  std::string name;  // the experiment, or "key=value, ..." of the group_by keys
  std::vector<int64_t> runs;
  int trials = 0;
  ProportionInterval pooled_success;                   // the trials of all the runs together
  std::map<std::string, std::vector<double>> samples;  // per metric, one per run having it
  std::map<std::string, MeanInterval> metrics;         // across runs; unclipped
  // What the group pools besides seeds: its experiments when it has several,
  // and the settings (sweep axes, resolved config; not seeds or the group_by
  // keys) whose values differ between its runs of one experiment.
  std::vector<std::string> experiments;  // in the order of their first run
  std::vector<std::string> differing;    // sorted
};

// Task success of `group` against `versus` (group minus versus).
struct SuccessDifference {
  std::string group, versus;
  ProportionInterval group_pooled, versus_pooled;
  double pooled_difference = 0.0;   // of the pooled rates
  double fisher_p = 0.0;            // two-sided, on the pooled 2x2 table
  DifferenceInterval across_seeds;  // of the mean task_success_rate (Welch); unclipped
};

struct RunComparison {
  std::string grouping;                                   // "experiment" or the group_by keys
  std::vector<std::string> metrics;                       // the metric columns, in order
  std::map<std::string, MetricDeclaration> declarations;  // of the metric columns, by name
  std::vector<RunGroup> groups;                           // in the order of their first run
  std::vector<SuccessDifference> differences;
};

// Throws ComparisonError without runs, when no run has a group_by key (every
// run would be "(unset)") or when the baseline is not a group.
RunComparison compare_runs(const std::vector<RunSummary>& runs, const ComparisonOptions& options);

// One line per group that pools more than seeds: "group G pools experiments
// a, b" and/or "... runs that differ in k1, k2"; empty when none does.
std::vector<std::string> pooling_notes(const RunComparison& comparison);

// The grouping key of a run: its experiment, or the group_by values.
std::string group_name(const RunSummary& run, const std::vector<std::string>& group_by);

std::string comparison_markdown(const RunComparison& comparison);
// One row per group metric (kind "mean"), per group's pooled success (kind
// "pooled_success") and per difference (kind "difference"); see the header.
std::string comparison_csv(const RunComparison& comparison);

}  // namespace corrmp
