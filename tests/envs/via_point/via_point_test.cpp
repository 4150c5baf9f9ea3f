// Tests of the via-point reach: the expert's demonstrations and decisions,
// the outcome's failure categories, refused parameters, and the paths.
#include "envs/via_point/via_point.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/parameter_error.hpp"
#include "envs/via_point/via_point_expert.hpp"
#include "envs/via_point/via_point_paths.hpp"

namespace corrmp {
namespace {

TEST(ViaPoint, TheExpertPassesTheViaPointAndReachesTheGoalWithTheDecisionItsBendNames) {
  ViaPoint env{ViaPointParams{}};
  ViaPointExpert expert{ViaPointExpertParams{}};
  Rng rng(5);
  std::map<std::string, int> decisions;
  for (int i = 0; i < 60; ++i) {
    const Scenario scenario = env.sample_scenario(rng);
    const double offset = scenario.at("via_offset");
    ASSERT_LE(std::abs(offset), 0.03);
    const Demonstration demo = expert.demonstrate(env, scenario, false);
    const Outcome outcome = env.outcome();
    EXPECT_TRUE(outcome.success) << scenario_json(scenario) << ": " << outcome.failure;
    EXPECT_LT(outcome.details.at("via_distance"), 1e-4);
    EXPECT_EQ(demo.decision, offset > 0.005 ? "above" : offset < -0.005 ? "below" : "straight");
    // The demonstrated cor-MP is classified as the decision it implements.
    EXPECT_EQ(env.classify_decision(demo.find("cor")->y), demo.decision);
    ++decisions[demo.decision];
    ASSERT_EQ(demo.segments.size(), 4u);
    EXPECT_EQ(demo.find("full")->y.rows(), 100);
    // The whole recording's critical points follow the cor-MP's length.
    EXPECT_NEAR(demo.find("pre")->phase_end, demo.find("cor")->phase_begin, 1e-12);
    EXPECT_LT(demo.find("pre")->phase_end, demo.find("cor")->phase_end);
  }
  EXPECT_GT(decisions["above"], 10);
  EXPECT_GT(decisions["below"], 10);
  EXPECT_GT(decisions["straight"], 2);
}

TEST(ViaPoint, AStraightReachMissesAnOffsetViaPointAndSaysByHowMuch) {
  ViaPoint env{ViaPointParams{}};
  env.reset({{"via_offset", 0.02}});
  EXPECT_EQ(env.execute("full", straight_path({0.0, 0.0}, env.goal(), 50)), "");
  const Outcome outcome = env.outcome();
  EXPECT_FALSE(outcome.success);
  EXPECT_EQ(outcome.failure, "missed the via point by 20.0 mm");
  EXPECT_NEAR(outcome.details.at("via_distance"), 0.02, 1e-12);
  EXPECT_EQ(outcome.metrics.at("passed_via"), 0.0);
  EXPECT_EQ(outcome.metrics.at("reached_goal"), 1.0);
  EXPECT_EQ(env.classify_decision(straight_path({0.1, 0.0}, {0.2, 0.0}, 40)), "straight");
}

TEST(ViaPoint, APathThroughTheViaPointThatStopsShortMissesTheGoal) {
  ViaPoint env{ViaPointParams{}};
  env.reset({{"via_offset", -0.01}});
  EXPECT_EQ(env.execute("pre", straight_path({0.0, 0.0}, env.critical_point(), 30)), "");
  const Eigen::MatrixXd bend = bend_path(env.critical_point(), env.after_via(), -0.01, 40);
  EXPECT_EQ(env.execute("cor", bend), "");
  EXPECT_EQ(env.executed_path(), bend);  // walked exactly
  const Outcome outcome = env.outcome();
  EXPECT_FALSE(outcome.success);
  EXPECT_EQ(outcome.failure, "missed the goal by 100.0 mm");
  EXPECT_EQ(outcome.metrics.at("passed_via"), 1.0);
  EXPECT_EQ(outcome.metrics.at("reached_goal"), 0.0);
}

TEST(ViaPoint, ANonFiniteTrajectoryStopsTheTrialAsAnInvalidTrajectory) {
  ViaPoint env{ViaPointParams{}};
  Eigen::MatrixXd path = straight_path({0.0, 0.0}, {0.1, 0.0}, 10);
  path(4, 1) = std::nan("");
  EXPECT_EQ(env.execute("pre", path).rfind("invalid trajectory", 0), 0u);
  EXPECT_EQ(env.executed_path().rows(), 0);
  EXPECT_EQ(env.outcome().failure.rfind("invalid trajectory", 0), 0u);
  EXPECT_EQ(env.report().failure_categories.back(), "invalid trajectory");
}

TEST(ViaPoint, AnApproachThatLeavesTheReachIsRefusedAtItsKey) {
  using ::testing::HasSubstr;
  using ::testing::Property;
  using ::testing::Throws;
  using ::testing::ThrowsMessage;
  ViaPointParams behind;
  behind.approach = 0.2;
  const auto make_behind = [&] { ViaPoint{behind}; };
  EXPECT_THAT(make_behind, ThrowsMessage<ParameterError>(HasSubstr("behind the start")));
  EXPECT_THAT(make_behind, Throws<ParameterError>(Property(&ParameterError::key, "approach")));
  ViaPointParams beyond;
  beyond.via_x = 0.28;
  const auto make_beyond = [&] { ViaPoint{beyond}; };
  EXPECT_THAT(make_beyond, ThrowsMessage<ParameterError>(HasSubstr("beyond the goal")));
  EXPECT_THAT(make_beyond, Throws<ParameterError>(Property(&ParameterError::key, "approach")));
}

TEST(ViaPointPaths, ResamplingByLengthWalksAtConstantSpeed) {
  Eigen::MatrixXd corner(3, 2);
  corner << 0.0, 0.0, 0.3, 0.0, 0.3, 0.1;  // 0.4 long
  const Eigen::MatrixXd walked = resample_by_length(corner, 5);
  for (Eigen::Index i = 1; i < walked.rows(); ++i) {
    EXPECT_NEAR(path_length(walked.middleRows(i - 1, 2)), 0.1, 1e-12) << i;
  }
  EXPECT_NEAR(walked(3, 0), 0.3, 1e-12);
  EXPECT_NEAR(walked(3, 1), 0.0, 1e-12);
  EXPECT_NEAR(closest_distance(corner, {0.15, 0.05}), 0.05, 1e-12);
  EXPECT_NEAR(closest_distance(corner, {0.4, 0.05}), 0.1, 1e-12);
}

TEST(ViaPointPaths, TheBendPassesItsViaPointHalfwayAndEndsOnTheLine) {
  const Eigen::MatrixXd bend = bend_path({0.1, 0.0}, {0.2, 0.0}, 0.025, 41);
  EXPECT_NEAR(bend(20, 0), 0.15, 1e-12);
  EXPECT_NEAR(bend(20, 1), 0.025, 1e-12);
  EXPECT_NEAR(bend(0, 1), 0.0, 1e-12);
  EXPECT_NEAR(bend(40, 1), 0.0, 1e-12);
}

}  // namespace
}  // namespace corrmp
