// Tests of what a run stores of its task (its TaskReport, core/task_declaration.hpp), read back
// by the reports, which take the task's unit and label order from it.
#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "evaluation/evaluation_tables.hpp"
#include "report/decision_table.hpp"
#include "report/run_report.hpp"
#include "store/run_queries.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

// A task that is neither of the built-in ones: millimetres, labels b before a.
TaskReport reach_task() {
  TaskReport task;
  task.trajectory_columns = {"u", "v"};
  task.error_unit = "mm";
  task.error_scale = 1000.0;
  task.error_segments = {"reach"};
  task.error_columns = {0, 1};
  task.decision_segment = "reach";
  task.decision_labels = {"b", "a"};
  task.relative_columns = {1};
  task.plot_horizontal = 1;
  task.plot_vertical = 0;
  task.outcome_metrics = {"touched"};
  task.failure_categories = {"missed"};
  return task;
}

// A run of that task recorded as the pipeline records it: the run table's error column is in the
// task's unit, and its decisions are listed in the task's label order, not the trials' order.
TEST(RecordedTask, TheReportsShowTheTasksUnitAndLabelOrder) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  const TaskReport task = reach_task();
  RunRecord run;
  run.experiment = "reach_demo";
  run.config = "seed: 0\n";
  run.config_hash = "h";
  run.task = task;
  const int64_t id = store.begin_run(run);
  std::vector<EvaluatedTrial> evaluated(3);
  std::vector<TrialRecord> trials;
  const char* expected[] = {"a", "b", "a"};
  for (int t = 0; t < 3; ++t) {
    evaluated[t].trial = t;
    evaluated[t].expected_action = expected[t];
    evaluated[t].chosen_action = t == 2 ? "b" : expected[t];
    evaluated[t].success = t != 2;
    evaluated[t].failure = t == 2 ? "missed" : "";
    trials.push_back({t, "{}", evaluated[t].expected_action, evaluated[t].chosen_action,
                      evaluated[t].success, evaluated[t].failure, ""});
  }
  store.complete_run(id, trials,
                     evaluation_metrics(task, true, evaluated, {{"reach", {2.5, 4.0}}}));

  const auto runs = load_run_summaries(store, {});
  ASSERT_EQ(runs.size(), 1u);
  const std::string table = report_markdown(runs, {});
  EXPECT_NE(table.find("| reach-MP error mean / max (mm) |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 2 of 3 | 67% | 2.50 / 4.00 |"), std::string::npos) << table;
  const std::string decisions = decision_markdown(runs);
  EXPECT_NE(decisions.find("| 1 | reach_demo | b | 1 | 1 b | 100% | 100% |\n"
                           "| 1 | reach_demo | a | 2 | 1 b, 1 a | 50% | 50% |\n"),
            std::string::npos)
      << decisions;
}

}  // namespace
}  // namespace corrmp
