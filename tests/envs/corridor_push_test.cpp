// Tests of the corridor task: determinism, the expert's success rate and
// decisions, the executed path, the correction classifier, path sampling, and parallel
// collection with clones of the environment.
#include "envs/corridor_push/corridor_push.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "core/thread_budget.hpp"
#include "envs/corridor_push/corridor_expert.hpp"
#include "envs/corridor_push/path_sampling.hpp"

namespace corrmp {
namespace {

TEST(CorridorPush, TheSameScenarioReplaysIdentically) {
  CorridorPush env{CorridorPushParams{}};
  CorridorExpert expert{CorridorExpertParams{}};
  const Scenario scenario{{"corridor_offset", 0.021}, {"object_dx", 0.0}, {"object_dy", 0.0}};
  const Demonstration first = expert.demonstrate(env, scenario, false);
  const Eigen::Vector3d object = env.object_position();
  const Demonstration second = expert.demonstrate(env, scenario, false);
  EXPECT_EQ(object, env.object_position());
  for (size_t s = 0; s < first.segments.size(); ++s) {
    EXPECT_EQ(first.segments[s].y, second.segments[s].y);
  }
  EXPECT_EQ(first.decision, "push");
}

TEST(CorridorPush, TheExpertSucceedsOnAtLeast98PercentOfScenariosWithTheRightDecisions) {
  CorridorPush env{CorridorPushParams{}};
  CorridorExpert expert{CorridorExpertParams{}};
  Rng rng(123);
  int successes = 0, trials = 60;
  std::map<std::string, int> decisions;
  for (int i = 0; i < trials; ++i) {
    const Scenario scenario = env.sample_scenario(rng);
    const double offset = scenario.at("corridor_offset");
    ASSERT_LE(std::abs(offset), 0.03);
    const Demonstration demo = expert.demonstrate(env, scenario, false);
    const Outcome outcome = env.outcome();
    successes += outcome.success;
    EXPECT_TRUE(outcome.success) << scenario_json(scenario) << ": " << outcome.failure;
    const std::string expected = offset > 0.006 ? "push" : offset < -0.006 ? "pull" : "none";
    if (std::abs(std::abs(offset) - 0.006) > 0.001) {
      EXPECT_EQ(demo.decision, expected);
    }
    ++decisions[demo.decision];
    // The demonstrated cor-MP is classified as the decision it implements.
    EXPECT_EQ(env.classify_decision(demo.find("cor")->y), demo.decision);
    // After the correction the object was aligned with the corridor.
    ASSERT_EQ(demo.segments.size(), 4u);
    EXPECT_EQ(demo.find("full")->y.rows(), 140);
  }
  EXPECT_GE(successes, 0.98 * trials);
  EXPECT_GT(decisions["push"], 10);
  EXPECT_GT(decisions["pull"], 10);
  EXPECT_GT(decisions["none"], 2);
}

TEST(CorridorPush, DeclaresTheStateValuesItObserves) {
  CorridorPush env{CorridorPushParams{}};
  std::vector<std::string> keys;
  for (const auto& [key, value] : env.observe(false).state) keys.push_back(key);
  EXPECT_EQ(keys, env.state_names());  // both sorted
}

// The corridor's trajectories are gripper positions in metres; its errors are in centimetres.
TEST(CorridorPush, DeclaresItsColumnsAndErrorUnit) {
  const TaskReport task = CorridorPush{CorridorPushParams{}}.report();
  EXPECT_EQ(task.trajectory_columns, (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(task.error_unit, "cm");
  EXPECT_EQ(task.error_scale, 100.0);
}

TEST(CorridorPush, TouchingTheCorridorFailsTheTrial) {
  CorridorPush env{CorridorPushParams{}};
  const Scenario scenario{{"corridor_offset", 0.025}, {"object_dx", 0.0}, {"object_dy", 0.0}};
  env.reset(scenario);
  // Push straight through without correcting: the object hits the corridor wall.
  const Eigen::Vector3d start = env.effector_position().transpose();
  const Eigen::Vector3d object = env.object_position();
  const Eigen::MatrixXd straight =
      sample_path({start, {object.x(), start.y(), 0.03}, {object.x(), 0.12, 0.03}}, 60);
  EXPECT_EQ(env.execute("pre", straight), "");
  const Outcome outcome = env.outcome();
  EXPECT_FALSE(outcome.success);
  EXPECT_EQ(outcome.failure, "the object touched the corridor");
}

TEST(CorridorPush, RecordsTheExecutedPathRowForRowUpToWhereExecutionStopped) {
  CorridorPush env{CorridorPushParams{}};
  env.reset({{"corridor_offset", 0.0}, {"object_dx", 0.0}, {"object_dy", 0.0}});
  EXPECT_EQ(env.executed_path().rows(), 0);
  const Eigen::Vector3d start = env.effector_position().transpose();
  const Eigen::MatrixXd path = sample_path({start, start + Eigen::Vector3d(0.0, 0.03, 0.0)}, 20);
  ASSERT_EQ(env.execute("pre", path), "");
  // The floating gripper is where it was commanded at every row.
  ASSERT_EQ(env.executed_path().rows(), path.rows());
  ASSERT_EQ(env.executed_path().cols(), 3);
  EXPECT_LT((env.executed_path() - path).cwiseAbs().maxCoeff(), 1e-12);
  Eigen::MatrixXd broken = sample_path({path.bottomRows(1).transpose(), start}, 10);
  broken(4, 1) = std::nan("");
  EXPECT_NE(env.execute("cor", broken), "");
  ASSERT_EQ(env.executed_path().rows(), 4);
  EXPECT_LT((env.executed_path() - broken.topRows(4)).cwiseAbs().maxCoeff(), 1e-12);
  // Nothing runs after a failure, and nothing is recorded.
  EXPECT_NE(env.execute("post", path), "");
  EXPECT_EQ(env.executed_path().rows(), 0);
}

// The same scenario demonstrated at two human tempos: the same strokes, the
// critical points at different times of the whole-skill recording.
TEST(CorridorExpert, TempoMovesTheCriticalPointsInTimeButNotThePath) {
  CorridorPush env{CorridorPushParams{}};
  CorridorExpertParams params;
  params.tempo_variation = 0.3;
  CorridorExpert expert{params};
  const Scenario scenario{{"corridor_offset", -0.02}, {"object_dx", 0.0}, {"object_dy", 0.0}};
  Rng first_rng(1), second_rng(2);
  const Demonstration nominal = expert.demonstrate(env, scenario, false);
  const Demonstration first = expert.demonstrate(env, scenario, false, &first_rng);
  const Demonstration second = expert.demonstrate(env, scenario, false, &second_rng);
  for (const Demonstration* demo : {&nominal, &first, &second}) {
    EXPECT_EQ(demo->decision, "pull");
    // The segments tile the skill's time, and the recording passes each
    // critical point (a segment's last point) at the segment's phase end.
    const Eigen::MatrixXd& full = demo->find("full")->y;
    double begin = 0.0;
    for (const char* name : {"pre", "cor", "post"}) {
      const SegmentTrajectory& s = *demo->find(name);
      EXPECT_EQ(s.phase_begin, begin) << name;
      EXPECT_GT(s.phase_end, s.phase_begin) << name;
      begin = s.phase_end;
      const auto at = static_cast<Eigen::Index>(std::lround(s.phase_end * (full.rows() - 1)));
      double nearest = 1.0;
      for (Eigen::Index row = std::max<Eigen::Index>(at - 1, 0);
           row <= std::min<Eigen::Index>(at + 1, full.rows() - 1); ++row) {
        nearest = std::min(nearest, (full.row(row) - s.y.bottomRows(1)).norm());
      }
      EXPECT_LT(nearest, 1e-12) << name;
    }
    EXPECT_DOUBLE_EQ(begin, 1.0);
    // Only the ticks at which contacts are resolved differ: the object ends
    // where it does at the nominal tempo to well under a millimetre.
    EXPECT_LT((demo->find("full")->y.bottomRows(1) - nominal.find("full")->y.bottomRows(1)).norm(),
              1e-4);
    EXPECT_EQ(demo->find("cor")->y.topRows(1), nominal.find("cor")->y.topRows(1));
  }
  EXPECT_NE(first.find("pre")->phase_end, second.find("pre")->phase_end);
  EXPECT_NE(first.find("cor")->y, second.find("cor")->y);
  // Without variation the collecting expert is the nominal one.
  params.tempo_variation = 0.0;
  Rng unused(3);
  const Demonstration steady = CorridorExpert{params}.demonstrate(env, scenario, false, &unused);
  for (size_t s = 0; s < nominal.segments.size(); ++s) {
    EXPECT_EQ(steady.segments[s].y, nominal.segments[s].y);
    EXPECT_EQ(steady.segments[s].phase_end, nominal.segments[s].phase_end);
  }
}

// A sweep over the tempo variation compares the same scenarios.
TEST(CorridorExpert, TheScenariosCollectedDoNotDependOnTheTempoVariation) {
  CorridorPush env{CorridorPushParams{}};
  std::vector<std::vector<std::string>> scenarios;
  for (double variation : {0.0, 0.3}) {
    CorridorExpertParams params;
    params.train = 3;
    params.validation = 1;
    params.tempo_variation = variation;
    Rng rng(7);
    const DemonstrationSplit split = CorridorExpert{params}.collect(&env, rng);
    scenarios.emplace_back();
    for (const auto* set : {&split.train, &split.validation}) {
      for (const auto& demo : *set) scenarios.back().push_back(demo.scenario);
    }
  }
  ASSERT_EQ(scenarios[0].size(), 4u);
  EXPECT_EQ(scenarios[0], scenarios[1]);
}

// Parallel collection: each attempt draws from its own stream and
// each thread demonstrates in its own clone of the environment, so the split,
// images included, is the same for any thread budget.
TEST(CorridorExpert, CollectsTheSameDemonstrationsWhateverTheThreadBudget) {
  CorridorExpertParams params;
  params.train = 6;
  params.validation = 3;
  params.images = true;
  std::vector<DemonstrationSplit> splits;
  const int saved = thread_budget();
  for (int budget : {1, 2}) {
    set_thread_budget(budget);
    CorridorPush env{CorridorPushParams{}};
    Rng rng(7);
    splits.push_back(CorridorExpert{params}.collect(&env, rng));
  }
  set_thread_budget(saved);
  const DemonstrationSplit& one = splits[0];
  const DemonstrationSplit& two = splits[1];
  ASSERT_EQ(one.train.size(), 6u);
  ASSERT_EQ(one.validation.size(), 3u);
  ASSERT_EQ(two.train.size(), 6u);
  ASSERT_EQ(two.validation.size(), 3u);
  for (const auto set : {&DemonstrationSplit::train, &DemonstrationSplit::validation}) {
    for (size_t d = 0; d < (one.*set).size(); ++d) {
      const Demonstration& a = (one.*set)[d];
      const Demonstration& b = (two.*set)[d];
      EXPECT_EQ(a.scenario, b.scenario);
      EXPECT_EQ(a.decision, b.decision);
      ASSERT_EQ(a.segments.size(), b.segments.size());
      for (size_t s = 0; s < a.segments.size(); ++s) {
        EXPECT_EQ(a.segments[s].y, b.segments[s].y);
        EXPECT_EQ(a.segments[s].phase_end, b.segments[s].phase_end);
        EXPECT_EQ(a.segments[s].start.state, b.segments[s].start.state);
        const cv::Mat& image_a = a.segments[s].start.rgb;
        const cv::Mat& image_b = b.segments[s].start.rgb;
        ASSERT_EQ(image_a.empty(), image_b.empty());
        if (!image_a.empty()) {
          EXPECT_EQ(cv::norm(image_a, image_b, cv::NORM_INF), 0.0);
          EXPECT_EQ(cv::norm(a.segments[s].start.depth, b.segments[s].start.depth, cv::NORM_INF),
                    0.0);
        }
      }
    }
  }
  // The demonstrations are of different scenarios.
  EXPECT_NE(one.train[0].scenario, one.train[1].scenario);
}

TEST(CorridorPush, AClonePlaysTheSameScenarioIdentically) {
  CorridorPushParams params;
  params.corridor_range = 0.05;
  CorridorPush env{params};
  const std::unique_ptr<Environment> clone = env.clone();
  ASSERT_NE(dynamic_cast<CorridorPush*>(clone.get()), nullptr);
  EXPECT_EQ(static_cast<CorridorPush&>(*clone).params().corridor_range, 0.05);
  CorridorExpert expert{CorridorExpertParams{}};
  const Scenario scenario{{"corridor_offset", -0.02}, {"object_dx", 0.004}, {"object_dy", 0.0}};
  const Demonstration original = expert.demonstrate(env, scenario, false);
  const Demonstration copied = expert.demonstrate(*clone, scenario, false);
  for (size_t s = 0; s < original.segments.size(); ++s) {
    EXPECT_EQ(original.segments[s].y, copied.segments[s].y);
  }
  EXPECT_EQ(env.object_position(), static_cast<CorridorPush&>(*clone).object_position());
}

TEST(PathSampling, KeepsEveryWaypointAndSpacesPointsEvenly) {
  const std::vector<Eigen::Vector3d> waypoints{{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}};
  const Eigen::MatrixXd path = sample_path(waypoints, 21);
  ASSERT_EQ(path.rows(), 21);
  EXPECT_EQ(path.row(0), Eigen::RowVector3d(0, 0, 0));
  EXPECT_EQ(path.row(10), Eigen::RowVector3d(0.1, 0, 0));
  EXPECT_EQ(path.row(20), Eigen::RowVector3d(0.1, 0.1, 0));
  for (int i = 1; i < 21; ++i) EXPECT_NEAR((path.row(i) - path.row(i - 1)).norm(), 0.01, 1e-12);
  const Eigen::MatrixXd still = sample_path({{1, 2, 3}, {1, 2, 3}}, 5);
  EXPECT_EQ(still.row(4), Eigen::RowVector3d(1, 2, 3));
  EXPECT_THROW(sample_path(waypoints, 2), std::invalid_argument);
  EXPECT_EQ(normalised_time(3)(1, 0), 0.5);
  EXPECT_NEAR(weighted_length(waypoints), 0.2, 1e-15);
  EXPECT_NEAR(weighted_length(waypoints, {3.0, 1.0}), 0.4, 1e-15);
}

}  // namespace
}  // namespace corrmp
