// A task's declaration as stored with its runs (recorded_task.hpp).
#include "experiment/recorded_task.hpp"

namespace corrmp {

TaskDeclaration recorded_task(const TaskReport& report) {
  TaskDeclaration task;
  task.trajectory_columns = report.trajectory_columns;
  task.error_unit = report.error_unit;
  task.error_scale = report.error_scale;
  task.error_segments = report.error_segments;
  task.error_columns = report.error_columns;
  task.decision_segment = report.decision_segment;
  task.decision_labels = report.decision_labels;
  task.relative_columns = report.relative_columns;
  task.plot_horizontal = report.plot_horizontal;
  task.plot_vertical = report.plot_vertical;
  task.outcome_metrics = report.outcome_metrics;
  task.failure_categories = report.failure_categories;
  return task;
}

}  // namespace corrmp
