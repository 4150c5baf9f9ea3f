// The robot's run metrics from hand-made trials: the IK's success rate over all solves, the
// joint tracking error's mean and max over the trials' largest, and none without the details.
#include "sim/robot/robot_run_metrics.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

EvaluatedTrial trial_with(double tracking_error, double solves, double failures) {
  EvaluatedTrial trial;
  trial.details = {{"max_tracking_error", tracking_error},
                   {"ik_solves", solves},
                   {"ik_failures", failures},
                   {"critical_end_dx", 0.01}};
  return trial;
}

const Metric* find(const std::vector<Metric>& metrics, const std::string& name) {
  for (const auto& m : metrics) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

TEST(RobotRunMetrics, SuccessRateAndTrackingErrorOverTheTrials) {
  EvaluatedTrial floating;  // a trial without the robot's details is left out
  const std::vector<EvaluatedTrial> trials{trial_with(0.002, 300, 0), trial_with(0.004, 100, 1),
                                           floating};
  const std::vector<Metric> metrics = robot_run_metrics(trials);
  ASSERT_EQ(metrics.size(), 4u);
  const Metric* rate = find(metrics, "ik_success_rate");
  ASSERT_NE(rate, nullptr);
  EXPECT_DOUBLE_EQ(rate->value, 1.0 - 1.0 / 400.0);
  EXPECT_EQ(rate->declaration, rate_metric(Better::higher));
  EXPECT_DOUBLE_EQ(find(metrics, "ik_solves")->value, 400.0);
  const Metric* mean = find(metrics, "joint_tracking_error_mean_rad");
  const Metric* max = find(metrics, "joint_tracking_error_max_rad");
  ASSERT_NE(mean, nullptr);
  ASSERT_NE(max, nullptr);
  EXPECT_DOUBLE_EQ(mean->value, 0.003);
  EXPECT_DOUBLE_EQ(max->value, 0.004);
  // One report column: the mean and the max under one heading, in rad, lower is better.
  EXPECT_EQ(mean->declaration.heading, max->declaration.heading);
  EXPECT_EQ(mean->declaration.statistic, "mean");
  EXPECT_EQ(max->declaration.statistic, "max");
  EXPECT_EQ(max->declaration.unit, "rad");
  EXPECT_EQ(max->declaration.better, Better::lower);
}

TEST(RobotRunMetrics, TrialsWithoutSolvesHaveNoSuccessRate) {
  const std::vector<Metric> metrics = robot_run_metrics({trial_with(0.0, 0, 0)});
  EXPECT_EQ(find(metrics, "ik_success_rate"), nullptr);
  ASSERT_NE(find(metrics, "ik_solves"), nullptr);
  EXPECT_EQ(find(metrics, "ik_solves")->value, 0.0);
}

TEST(RobotRunMetrics, NoTrialWithTheDetailsGivesNoMetrics) {
  EXPECT_TRUE(robot_run_metrics({EvaluatedTrial{}, EvaluatedTrial{}}).empty());
  EXPECT_TRUE(robot_run_metrics({}).empty());
}

TEST(RobotRunMetrics, TheIkTimeLineNamesTheRunAndTheTimePerSolve) {
  IkSolveTimes times;
  EXPECT_EQ(ik_time_log_line(times, "run"), "");
  times.add(20e-6);
  times.add(40e-6);
  times.add(60e-6);
  const std::string line = ik_time_log_line(times, "run");
  EXPECT_EQ(line.rfind("IK time (run): 3 solves, median ", 0), 0u) << line;
  EXPECT_NE(line.find("mean 40.0 us per solve"), std::string::npos) << line;
}

}  // namespace
}  // namespace corrmp
