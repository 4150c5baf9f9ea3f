// Tests of each run's decisions by expected label (report/decision_table.hpp): in the order its
// task declared the labels, or, for a run recorded before tasks were stored, first seen first.
#include "report/decision_table.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "support/recorded_runs.hpp"

namespace corrmp {
namespace {

using testing::RunSpec;
using testing::TempDir;

TEST(DecisionTable, ARunsTaskOrdersItsLabelsAndTheChoices) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  RunSpec spec;
  spec.experiment = "corridor_pc";
  spec.trials = {
      {"pull", "none", false}, {"push", "push", true}, {"pull", "pull", true}, {"pull", "", false}};
  spec.metrics = {{"decision_match_rate", 0.5}};
  TaskDeclaration task;
  task.decision_labels = {"push", "none", "pull"};
  spec.task = task;
  testing::record_run(store, spec);
  const auto runs = load_run_summaries(store, {});
  EXPECT_EQ(decision_markdown(runs),
            "| run | experiment | expected | trials | action choice | decision match | task "
            "success |\n|---|---|---|---|---|---|---|\n"
            "| 1 | corridor_pc | push | 1 | 1 push | 100% | 100% |\n"
            "| 1 | corridor_pc | pull | 3 | 1 none, 1 pull, 1 undecided | 33% | 33% |\n");
  EXPECT_EQ(decision_csv(runs),
            "run,experiment,expected,trials,chosen,matched,successes\n"
            "1,corridor_pc,push,1,1 push,1,1\n"
            "1,corridor_pc,pull,3,1 none; 1 pull; 1 undecided,1,1\n");
}

// Without its task's declaration (an older database) a run lists the labels its trials expected,
// first seen first; a policy that makes no decision (no decision_match_rate) has no match.
TEST(DecisionTable, ARunRecordedWithoutItsTaskListsItsLabelsFirstSeenFirst) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  RunSpec spec;
  spec.experiment = "corridor_mono";
  spec.trials = {{"pull", "pull", true}, {"push", "pull", false}, {"pull", "pull", true}};
  testing::record_run(store, spec);
  RunSpec curves;  // no decisions: no rows
  curves.experiment = "curves_demo";
  testing::record_run(store, curves);
  const auto runs = load_run_summaries(store, {});
  EXPECT_EQ(decision_labels(runs[0]), (std::vector<std::string>{"pull", "push"}));
  const std::string table = decision_markdown(runs);
  EXPECT_NE(table.find("| 1 | corridor_mono | pull | 2 | 2 pull | - | 100% |\n"
                       "| 1 | corridor_mono | push | 1 | 1 pull | - | 0% |\n"),
            std::string::npos)
      << table;
  EXPECT_EQ(table.find("curves_demo"), std::string::npos) << table;
}

}  // namespace
}  // namespace corrmp
