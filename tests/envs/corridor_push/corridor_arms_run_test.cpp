// configs/corridor_pc_arms.yaml end to end through run_experiment, shrunk to a
// few demonstrations, trials and updates: the trials run on the robot's arms, and
// the run records the robot's metrics and logs its IK time.
#include <gtest/gtest.h>

#include "report/run_summaries.hpp"
#include "store/result_store.hpp"
#include "support/report_tool.hpp"

namespace corrmp {
namespace {

const std::string kConfig = std::string(PROJECT_DIR) + "/configs/corridor_pc_arms.yaml";

TEST(CorridorArmsRun, ATinyRunEvaluatesItsTrialsOnTheArms) {
  testing::TempDir dir;
  const testing::ToolOutcome run = testing::run_experiment_tool(
      dir, kConfig +
               " demonstrations.train=4 demonstrations.validation=1 evaluation.trials=2"
               " policy.network.width=16 policy.training.updates=200"
               " policy.training.validate_every=100 --threads 1 --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ResultStore store(dir.file("r.sqlite"));
  const std::vector<RunSummary> runs = load_run_summaries(store, ReportQuery{});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs.front().trials, 2);
  EXPECT_EQ(runs.front().settings.at("environment.robot.type"), "dual_arm");
  ASSERT_TRUE(runs.front().task.has_value());
  EXPECT_EQ(runs.front().task->failure_categories,
            (std::vector<std::string>{"out of reach", "joint limit", "self collision",
                                      "tracking error", "physics fault", "physics blow-up",
                                      "the object touched the corridor", "the object stopped"}));
  EXPECT_EQ(runs.front().metrics.count("failures_out_of_reach"), 1u);
  // The robot's run metrics are recorded; its IK wall time is printed only.
  for (const char* metric : {"ik_solves", "ik_success_rate", "joint_tracking_error_mean_rad",
                             "joint_tracking_error_max_rad"}) {
    EXPECT_EQ(runs.front().metrics.count(metric), 1u) << metric;
  }
  EXPECT_GT(runs.front().metrics.at("ik_solves"), 0.0);
  // In the run's log, not in its tables, whose text the same config and seed reproduce.
  const std::string log = testing::read(runs.front().out_dir + "/log.txt");
  EXPECT_NE(log.find("IK time (corridor_pc_arms): "), std::string::npos) << log;
  const std::string tables = testing::read(runs.front().out_dir + "/tables.txt");
  ASSERT_FALSE(tables.empty());
  EXPECT_EQ(tables.find("IK time"), std::string::npos) << tables;
  for (const auto& [name, value] : runs.front().metrics) {
    if (name.rfind("ik_", 0) == 0) {
      EXPECT_TRUE(name == "ik_solves" || name == "ik_success_rate");
    }
  }
}

TEST(CorridorArmsRun, AnUnknownRobotTypeIsAConfigErrorNamingTheKey) {
  testing::TempDir dir;
  const testing::ToolOutcome run =
      testing::run_experiment_tool(dir, kConfig + " environment.robot.type=wheeled --quiet");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("environment.robot.type"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("wheeled"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace corrmp
