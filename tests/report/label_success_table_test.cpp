// The label rows of the per-label success table follow the order the runs' task declared.
#include "report/label_success_table.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

LabelSuccessSpec spec_ordering(std::vector<std::string> labels) {
  LabelSuccessSpec spec;
  spec.table = "t";
  spec.title = "Success per label";
  spec.text = "No reference.";
  spec.absent_text = "No runs.";
  spec.label_heading = "label";
  spec.experiments = {"lift"};
  spec.labels = std::move(labels);
  return spec;
}

RunSummary run_expecting(int64_t id, std::optional<TaskDeclaration> task) {
  RunSummary run;
  run.id = id;
  run.experiment = "lift";
  run.status = RunStatus::completed;
  run.trials = 4;
  run.task = std::move(task);
  run.expected_order = {"up", "down"};  // as its trials recorded them, first seen first
  run.metrics = {{"task_success_rate", 0.5},
                 {"expected_up", 2},
                 {"expected_down", 2},
                 {"task_success_rate_up", 1.0},
                 {"task_success_rate_down", 0.0}};
  return run;
}

// The position of each label's row in the section.
size_t row_of(const std::string& section, const std::string& label) {
  return section.find("| " + label + " |");
}

TEST(LabelSuccessTable, RowsFollowTheOrderTheTaskDeclared) {
  TaskDeclaration task;
  task.decision_labels = {"up", "down"};
  const RunSummary a = run_expecting(1, task), b = run_expecting(2, task);
  ReportCells cells;
  const std::string section =
      label_success_section(spec_ordering({"down", "up"}), {{"lift", {&a, &b}}}, cells);
  ASSERT_NE(row_of(section, "up"), std::string::npos) << section;
  ASSERT_NE(row_of(section, "down"), std::string::npos) << section;
  EXPECT_LT(row_of(section, "up"), row_of(section, "down")) << section;
}

TEST(LabelSuccessTable, RunsWithoutADeclarationTakeTheSpecsOrder) {
  const RunSummary a = run_expecting(1, std::nullopt), b = run_expecting(2, std::nullopt);
  ReportCells cells;
  const std::string section =
      label_success_section(spec_ordering({"down", "up"}), {{"lift", {&a, &b}}}, cells);
  ASSERT_NE(row_of(section, "up"), std::string::npos) << section;
  EXPECT_LT(row_of(section, "down"), row_of(section, "up")) << section;
}

}  // namespace
}  // namespace corrmp
