// The plain records a run writes to the result store and reads back: no database in sight, so
// that the code producing them (evaluation, pipeline) needs only this header.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/metric.hpp"

namespace corrmp {

// What a run's task declared of its reports (the environment's TaskReport, envs/environment.hpp),
// stored with the run so that reports read its labels, columns and units from the database.
struct TaskDeclaration {
  std::vector<std::string> trajectory_columns;
  std::string error_unit;
  double error_scale = 1.0;  // error units per trajectory unit
  std::vector<std::string> error_segments;
  std::vector<int> error_columns;
  std::string decision_segment;
  std::vector<std::string> decision_labels;  // in table order
  std::vector<int> relative_columns;
  int plot_horizontal = 0;
  int plot_vertical = 1;
  std::vector<std::string> outcome_metrics;
  std::vector<std::string> failure_categories;
};

inline bool operator==(const TaskDeclaration& a, const TaskDeclaration& b) {
  return a.trajectory_columns == b.trajectory_columns && a.error_unit == b.error_unit &&
         a.error_scale == b.error_scale && a.error_segments == b.error_segments &&
         a.error_columns == b.error_columns && a.decision_segment == b.decision_segment &&
         a.decision_labels == b.decision_labels && a.relative_columns == b.relative_columns &&
         a.plot_horizontal == b.plot_horizontal && a.plot_vertical == b.plot_vertical &&
         a.outcome_metrics == b.outcome_metrics && a.failure_categories == b.failure_categories;
}

struct RunRecord {
  std::string experiment;
  std::string config;  // resolved YAML
  std::string config_hash;
  uint64_t seed = 0;
  std::string git_commit;
  bool git_dirty = false;
  std::string out_dir;
  // Set for a run of a sweep: the sweep, the job's index and its axis values
  // (a JSON object, key -> value as written).
  std::string sweep_id;
  int job_index = 0;
  std::string axes;
  // What the run's task declares; none for a run without an environment.
  std::optional<TaskDeclaration> task{};
};

struct TrialRecord {
  int trial = 0;
  std::string scenario;  // JSON
  std::string expected_action;
  std::string chosen_action;
  bool success = false;
  std::string failure;  // empty on success
  std::string details;  // JSON: the trial's contexts and the task's outcome values
};

// A metric with its declaration (core/metric.hpp), as a run records it.
using MetricRecord = Metric;

}  // namespace corrmp
