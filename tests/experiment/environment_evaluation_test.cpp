// Tests of the closed-loop evaluation: a whole-skill policy that replays the
// expert's own recording succeeds, makes the expert's decisions, and its
// segments (cut at the reference's critical points) match the expert's.
#include "experiment/environment_evaluation.hpp"

#include <gtest/gtest.h>

#include <map>

#include "envs/corridor_push/corridor_expert.hpp"

namespace corrmp {
namespace {

// Row-wise linear interpolation of `y` (rows at times `t`, increasing) at `at`.
Eigen::MatrixXd interpolate(const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                            const Eigen::VectorXd& at) {
  Eigen::MatrixXd out(at.size(), y.cols());
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < at.size(); ++i) {
    while (k + 2 < t.size() && t(k + 1) < at(i)) ++k;
    const double u = std::clamp((at(i) - t(k)) / (t(k + 1) - t(k)), 0.0, 1.0);
    out.row(i) = (1 - u) * y.row(k) + u * y.row(k + 1);
  }
  return out;
}

// A monolithic "policy" that knows the answer: it looks up the corridor in
// the live environment and replays the expert's whole-skill recording.
class ReplayingPolicy : public Policy {
 public:
  explicit ReplayingPolicy(const CorridorPush& live) : live_(live), own_(CorridorPushParams{}) {
    own_.reset({{"corridor_offset", 0.0}, {"object_dx", 0.0}, {"object_dy", 0.0}});
    nominal_corridor_x_ = own_.corridor_x();
  }
  std::vector<PolicyTrainingSummary> fit(const std::vector<Demonstration>&,
                                         const std::vector<Demonstration>&, Rng&) override {
    return {};
  }
  std::vector<std::string> segments() const override { return {"full"}; }
  std::vector<std::string> context_segments() const override { return {}; }
  CnmpPrediction generate(const std::string& segment, const Eigen::MatrixXd&,
                          const Eigen::VectorXd&, const Eigen::MatrixXd& query_x) override {
    EXPECT_EQ(segment, "full");
    const double offset = live_.corridor_x() - nominal_corridor_x_;
    if (recordings_.count(offset) == 0) {
      const Scenario scenario{{"corridor_offset", offset}, {"object_dx", 0.0}, {"object_dy", 0.0}};
      recordings_[offset] =
          *CorridorExpert{CorridorExpertParams{}}.demonstrate(own_, scenario, false).find("full");
    }
    const SegmentTrajectory& full = recordings_[offset];
    const Eigen::MatrixXd mean = interpolate(full.x.col(0), full.y, query_x.col(0));
    return {mean, Eigen::MatrixXd::Zero(mean.rows(), mean.cols())};
  }
  void save(const std::string&) override {}

 private:
  const CorridorPush& live_;
  CorridorPush own_;
  double nominal_corridor_x_ = 0.0;
  std::map<double, SegmentTrajectory> recordings_;
};

TEST(EnvironmentEvaluation, AWholeSkillPolicyIsCutAtTheReferencesCriticalPoints) {
  CorridorPush environment{CorridorPushParams{}};
  CorridorExpert expert{CorridorExpertParams{}};
  ReplayingPolicy policy(environment);
  Rng rng(11);
  const int trials = 4;
  const EnvironmentEvaluation result =
      evaluate_in_environment(environment, expert, nullptr, policy, trials, rng, "replay");
  ASSERT_EQ(result.trials.size(), 4u);
  for (const TrialRecord& trial : result.trials) {
    EXPECT_TRUE(trial.success) << trial.scenario << ": " << trial.failure;
    EXPECT_EQ(trial.chosen_action, trial.expected_action) << trial.scenario;
  }
  std::map<std::string, double> metrics;
  for (const MetricRecord& m : result.metrics) metrics[m.name] = m.value;
  EXPECT_EQ(metrics.at("task_success_rate"), 1.0);
  EXPECT_EQ(metrics.at("decision_match_rate"), 1.0);
  // Read between the reference's critical points, the replayed recording is
  // the expert's cor-MP and post-MP up to interpolation (a fixed split by
  // point counts would be 0.5-0.9 cm off).
  EXPECT_LT(metrics.at("cor_mp_error_max_cm"), 0.1);
  EXPECT_LT(metrics.at("post_mp_error_max_cm"), 0.1);
  // Each trial's trajectories are returned for the files: the policy's
  // segments beside the expert's, point for point.
  ASSERT_EQ(result.evaluated.size(), 4u);
  for (int t = 0; t < trials; ++t) {
    const EvaluatedTrial& paths = result.evaluated[t];
    EXPECT_EQ(paths.trial, t);
    EXPECT_TRUE(paths.success);
    EXPECT_EQ(paths.chosen_action, result.trials[t].chosen_action);
    for (const char* segment : {"pre", "cor", "post"}) {
      ASSERT_EQ(paths.generated.count(segment), 1u) << segment;
      EXPECT_EQ(paths.generated.at(segment).rows(), paths.expert.at(segment).rows());
      EXPECT_LT((paths.generated.at(segment) - paths.expert.at(segment)).cwiseAbs().maxCoeff(),
                0.005)
          << segment;
    }
  }
  EXPECT_NE(result.tables.find("Table I (replay): 4 of 4 trials succeeded"), std::string::npos)
      << result.tables;
}

}  // namespace
}  // namespace corrmp
