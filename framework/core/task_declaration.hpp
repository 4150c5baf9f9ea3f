// What a task declares of its reports (an environment's report(), envs/environment.hpp): its
// trajectory columns, errors, decision labels, outcomes, failure categories and plot axes. The
// generic evaluation, tables and figures loop over it, and the result store keeps it with each
// run so that reports read a task's labels, columns and units from the database.
#pragma once

#include <string>
#include <vector>

namespace corrmp {

// What a task reports. Trajectories are in the task's own unit (metres for the
// Bullet tasks); errors are reported in `error_unit`, `error_scale` of them
// per trajectory unit. Every task declares its own columns and error unit.
struct TaskDeclaration {
  std::vector<std::string> trajectory_columns;
  std::string error_unit;
  double error_scale = 1.0;
  // Segments whose generated trajectory is compared with the expert's (the
  // paper's Table II), in table order; the metric names are
  // <segment>_mp_error_mean_<unit> and <segment>_mp_error_max_<unit>.
  std::vector<std::string> error_segments;
  // The trajectory columns the errors measure (positions, not a gripper's
  // opening); empty: all of them.
  std::vector<int> error_columns;
  // The decision made at the critical point (the paper's Table I): the segment
  // whose generated trajectory classify_decision() reads and the labels it
  // can return, in table order. No labels: the task has no such decision.
  std::string decision_segment;
  std::vector<std::string> decision_labels;
  // The columns a relative segment's rows give as offsets from the segment's
  // start (positions); the others stay absolute (a gripper's opening). Empty:
  // all of them.
  std::vector<int> relative_columns;
  // The two trajectory columns of the trajectories figure's panels.
  int plot_horizontal = 0;
  int plot_vertical = 1;
  // Names of Outcome::metrics every trial carries.
  std::vector<std::string> outcome_metrics;
  // Failure categories: a failed trial's reason starts with one of them, and
  // the tables count the failures per category.
  std::vector<std::string> failure_categories;
};

// Whether a failed trial's reason is of `category`: the reason starts with the category's name.
inline bool in_failure_category(const std::string& failure, const std::string& category) {
  return failure.rfind(category, 0) == 0;
}

// The run metric counting the failed trials of a failure category: failures_<category>, spaces
// as '_'.
inline std::string failure_count_metric(const std::string& category) {
  std::string name = "failures_" + category;
  for (char& c : name) {
    if (c == ' ') c = '_';
  }
  return name;
}

inline bool operator==(const TaskDeclaration& a, const TaskDeclaration& b) {
  return a.trajectory_columns == b.trajectory_columns && a.error_unit == b.error_unit &&
         a.error_scale == b.error_scale && a.error_segments == b.error_segments &&
         a.error_columns == b.error_columns && a.decision_segment == b.decision_segment &&
         a.decision_labels == b.decision_labels && a.relative_columns == b.relative_columns &&
         a.plot_horizontal == b.plot_horizontal && a.plot_vertical == b.plot_vertical &&
         a.outcome_metrics == b.outcome_metrics && a.failure_categories == b.failure_categories;
}

}  // namespace corrmp
