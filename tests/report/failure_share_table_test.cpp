// The failure-share table of the reproduction report, from a tiny results database: one row per
// experiment, one column per declared category, read from the runs' failures_<category> counts.
#include "report/failure_share_table.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "support/recorded_runs.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

TaskDeclaration declaring(std::vector<std::string> categories) {
  TaskDeclaration task;
  task.failure_categories = std::move(categories);
  return task;
}

// A run of `trials` trials of which `successes` succeeded, with the given failure counts.
testing::RunSpec run_of(const std::string& experiment, std::optional<TaskDeclaration> task,
                        int trials, int successes, std::vector<MetricRecord> failures) {
  testing::RunSpec spec;
  spec.experiment = experiment;
  spec.task = std::move(task);
  spec.trials = testing::trials_of("", trials, successes);
  spec.metrics = std::move(failures);
  spec.metrics.push_back({"task_success_rate", static_cast<double>(successes) / trials});
  return spec;
}

const ReportCell* find_cell(const ReportCells& cells, const std::string& row,
                            const std::string& group) {
  for (const auto& cell : cells.cells()) {
    if (cell.row == row && cell.group == group) return &cell;
  }
  return nullptr;
}

TEST(FailureShareTable, SharesArePooledPerExperimentOverTheDeclaredCategories) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  const MetricDeclaration count = count_metric(Better::lower);
  // Two runs of "reach" (10 trials each), whose task declares two categories.
  testing::record_run(store,
                      run_of("reach", declaring({"slipped", "too far"}), 10, 6,
                             {{"failures_slipped", 1, count}, {"failures_too_far", 2, count}}));
  testing::record_run(store,
                      run_of("reach", declaring({"slipped", "too far"}), 10, 8,
                             {{"failures_slipped", 0, count}, {"failures_too_far", 2, count}}));
  // One run of "grasp", whose task declares only the first, and one with no categories.
  testing::record_run(
      store, run_of("grasp", declaring({"slipped"}), 5, 3, {{"failures_slipped", 2, count}}));
  testing::record_run(store, run_of("plain", declaring({}), 4, 3, {}));
  const std::vector<RunSummary> runs = load_run_summaries(store, {});
  RunsOf runs_of;
  for (const auto& run : runs) runs_of[run.experiment].push_back(&run);

  ReportCells cells;
  const std::string md = failure_share_section(runs_of, {"reach", "grasp", "plain"}, cells);
  EXPECT_NE(md.find("| experiment | runs | trials | failed | slipped | too far | other |"),
            std::string::npos)
      << md;
  // reach: 6 of 20 failed, 1 slipped, 4 too far, 1 in no category.
  EXPECT_NE(md.find("| reach | 2 | 20 | 30% (6) | 5% (1) | 20% (4) | 5% (1) |"), std::string::npos)
      << md;
  // grasp does not declare "too far"; all its failures slipped.
  EXPECT_NE(md.find("| grasp | 1 | 5 | 40% (2) | 40% (2) | - | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| plain | 1 | 4 | 25% (1) | - | - | 25% (1) |"), std::string::npos) << md;

  const ReportCell* too_far = find_cell(cells, "reach", "too far");
  ASSERT_NE(too_far, nullptr);
  EXPECT_EQ(too_far->table, "failure_shares");
  EXPECT_EQ(too_far->runs, 2);
  EXPECT_DOUBLE_EQ(too_far->mean, 0.2);
  EXPECT_LT(too_far->low, 0.2);
  EXPECT_GT(too_far->high, 0.2);
  EXPECT_EQ(find_cell(cells, "grasp", "too far"), nullptr);  // not its category: no cell
}

TEST(FailureShareTable, RunsWhoseTasksDeclareNoCategoriesGetNoTable) {
  RunSummary run;
  run.experiment = "plain";
  run.trials = 4;
  run.successes = 2;
  run.task = TaskDeclaration{};
  ReportCells cells;
  const std::string md = failure_share_section({{"plain", {&run}}}, {"plain"}, cells);
  EXPECT_NE(md.find("No selected run's task declares failure categories."), std::string::npos)
      << md;
  EXPECT_EQ(md.find("| plain |"), std::string::npos) << md;
  EXPECT_TRUE(cells.cells().empty());
}

}  // namespace
}  // namespace corrmp
