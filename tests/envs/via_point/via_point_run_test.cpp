// configs/via_point_pc.yaml end to end through run_experiment: the segmented
// CNMPs with perfect context learn the reach from the expert and succeed on
// evaluation scenarios none of them was trained on.
#include <gtest/gtest.h>

#include "report/run_summaries.hpp"
#include "store/result_store.hpp"
#include "support/report_tool.hpp"

namespace corrmp {
namespace {

TEST(ViaPointRun, SegmentedCnmpsWithPerfectContextSucceedOnUnseenScenarios) {
  testing::TempDir dir;
  // Evaluation scenarios from a seed of their own, apart from the configs' evaluation seed.
  const testing::ToolOutcome run = testing::run_experiment_tool(
      dir, std::string(PROJECT_DIR) + "/configs/via_point_pc.yaml evaluation.seed=2024 --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  ResultStore store(dir.file("r.sqlite"));
  const std::vector<RunSummary> runs = load_run_summaries(store, ReportQuery{});
  ASSERT_EQ(runs.size(), 1u);
  const RunSummary& summary = runs.front();
  EXPECT_EQ(summary.experiment, "via_point_pc");
  EXPECT_EQ(summary.trials, 50);
  // Thresholds well below what the task reaches (docs/results.md), on an evaluation seed of its
  // own.
  EXPECT_GE(summary.metrics.at("task_success_rate"), 0.9);
  EXPECT_GE(summary.metrics.at("decision_match_rate"), 0.9);
  EXPECT_GE(summary.metrics.at("passed_via_rate"), 0.9);
  EXPECT_EQ(summary.metrics.at("reached_goal_rate"), 1.0);
  EXPECT_LT(summary.metrics.at("cor_mp_error_mean_mm"), 1.0);
  for (const char* label : {"above", "straight", "below"}) {
    EXPECT_GT(summary.by_expected.count(label), 0u) << label;
  }
}

}  // namespace
}  // namespace corrmp
