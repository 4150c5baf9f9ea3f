// Tests of the closed-loop evaluation: a whole-skill policy that replays the
// expert's own recording succeeds, makes the expert's decisions, and its
// segments (cut at the reference's critical points) match the expert's; on a
// made-up task, a relative segment starts from zero offsets and is executed
// from where the effector is, its executed path is kept up to where execution
// stopped, and a trial that throws is a failed trial. Trials
// run in parallel with the results of one thread, the extractor called in trial
// order.
#include "evaluation/environment_evaluation.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <thread>

#include "context/perfect_context.hpp"
#include "core/thread_budget.hpp"
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

// Sets the thread budget for a scope.
class BudgetForScope {
 public:
  explicit BudgetForScope(int budget) : saved_(thread_budget()) { set_thread_budget(budget); }
  ~BudgetForScope() { set_thread_budget(saved_); }

 private:
  int saved_;
};

// The perfect context of the whole skill: the corridor's x.
PerfectContext corridor_context() {
  PerfectContextParams params;
  params.segments = {{"full", {"corridor_x"}}};
  return PerfectContext(params);
}

// A monolithic "policy" that knows the answer: given the corridor's x as its
// context, it replays the expert's whole-skill recording.
class ReplayingPolicy : public Policy {
 public:
  ReplayingPolicy() : own_(CorridorPushParams{}) {
    own_.reset({{"corridor_offset", 0.0}, {"object_dx", 0.0}, {"object_dy", 0.0}});
    nominal_corridor_x_ = own_.corridor_x();
  }
  std::vector<PolicyTrainingSummary> fit(const std::vector<Demonstration>&,
                                         const std::vector<Demonstration>&, Rng,
                                         Networks) override {
    return {};
  }
  std::vector<std::string> segments() const override { return {"full"}; }
  std::vector<std::string> context_segments() const override { return {"full"}; }
  CnmpPrediction generate(const std::string& segment, const Eigen::MatrixXd&,
                          const Eigen::VectorXd& context, const Eigen::MatrixXd& query_x) override {
    EXPECT_EQ(segment, "full");
    const double offset = context(0) - nominal_corridor_x_;
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
  CorridorPush own_;
  double nominal_corridor_x_ = 0.0;
  std::map<double, SegmentTrajectory> recordings_;
};

TEST(EnvironmentEvaluation, AWholeSkillPolicyIsCutAtTheReferencesCriticalPoints) {
  CorridorPush environment{CorridorPushParams{}};
  CorridorExpert expert{CorridorExpertParams{}};
  PerfectContext context = corridor_context();
  ReplayingPolicy policy;
  Rng rng(11);
  const int trials = 4;
  const EnvironmentEvaluation result =
      evaluate_in_environment(environment, expert, &context, policy, trials, rng, "replay");
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
      // The whole skill's execution, cut as its generation is: the floating
      // gripper passed every commanded point.
      ASSERT_EQ(paths.executed.count(segment), 1u) << segment;
      EXPECT_EQ(paths.executed.at(segment).rows(), paths.generated.at(segment).rows());
      EXPECT_LT((paths.executed.at(segment) - paths.generated.at(segment)).cwiseAbs().maxCoeff(),
                0.002)
          << segment;
    }
  }
  EXPECT_NE(result.tables.find("Table I (replay): 4 of 4 trials succeeded"), std::string::npos)
      << result.tables;
}

// A made-up task on a line: the effector starts at 1; segment "move" is
// absolute, segment "nudge" relative in column 0 only (column 1 is a
// gripper-like flag). Success: the effector ends beyond 3.
class LineTask : public Environment {
 public:
  TaskReport report() const override {
    TaskReport task;
    task.trajectory_columns = {"position", "flag"};
    task.error_segments = {"move", "nudge"};
    task.error_scale = 1.0;
    task.error_unit = "m";
    task.relative_columns = {0};
    task.decision_segment = "nudge";
    task.decision_labels = {"forward", "back"};
    task.plot_horizontal = 1;
    task.plot_vertical = 0;
    return task;
  }
  Scenario sample_scenario(Rng& rng) const override { return {{"throw", rng.uniform()}}; }
  void reset(const Scenario& scenario) override {
    position_ = 1.0;
    if (scenario.at("throw") < throw_below_) throw std::runtime_error("cannot reset");
  }
  std::vector<SegmentInfo> segments() const override { return {{"move", 3}, {"nudge", 3, true}}; }
  Eigen::RowVectorXd effector_position() const override {
    Eigen::RowVectorXd row(2);
    row << position_, 7.0;
    return row;
  }
  std::string execute(const std::string& segment, const Eigen::MatrixXd& rows) override {
    executed_.push_back(rows);
    if (segment == stop_in_) {
      // Stops after its first two rows, which it executed `lag` short.
      reached_ = rows.topRows(2);
      reached_.col(0).array() -= lag_;
      return "stopped";
    }
    reached_ = rows;
    reached_.col(0).array() -= lag_;
    position_ =
        segment == "nudge" ? position_ + rows(rows.rows() - 1, 0) : rows(rows.rows() - 1, 0);
    return "";
  }
  Eigen::MatrixXd executed_path() const override { return record_ ? reached_ : Eigen::MatrixXd(); }
  Observation observe(bool) override { return {}; }
  std::vector<std::string> state_names() const override { return {}; }
  Outcome outcome() const override {
    return {position_ > 3.0, position_ > 3.0 ? "" : "short", {}, {}};
  }
  std::string classify_decision(const Eigen::MatrixXd& rows) const override {
    return rows(rows.rows() - 1, 0) > rows(0, 0) ? "forward" : "back";
  }

  double throw_below_ = -1.0;
  double position_ = 1.0;
  std::vector<Eigen::MatrixXd> executed_;
  bool record_ = false;  // reports the executed path
  double lag_ = 0.0;     // by which the execution falls short in column 0
  std::string stop_in_;  // the segment whose execution stops
  Eigen::MatrixXd reached_;
};

// The expert: to 2 (absolute), then 1.5 further (relative).
class LineExpert : public DemonstrationSource {
 public:
  DemonstrationSplit collect(Environment*, Rng&) override { return {}; }
  bool can_demonstrate() const override { return true; }
  Demonstration demonstrate(Environment&, const Scenario&, bool) override {
    Demonstration demo;
    demo.decision = "forward";
    Eigen::MatrixXd move(3, 2), nudge(3, 2);
    move << 1, 7, 1.5, 7, 2, 7;
    nudge << 0, 7, 0.75, 7, 1.5, 7;
    demo.segments.push_back({"move", Eigen::VectorXd::LinSpaced(3, 0, 1), move, {}, {}});
    demo.segments.push_back({"nudge", Eigen::VectorXd::LinSpaced(3, 0, 1), nudge, {}, {}});
    return demo;
  }
};

// The policy: goes to 2.5, then 1.0 further; it records the start rows it was given.
class LinePolicy : public Policy {
 public:
  std::vector<PolicyTrainingSummary> fit(const std::vector<Demonstration>&,
                                         const std::vector<Demonstration>&, Rng,
                                         Networks) override {
    return {};
  }
  std::vector<std::string> segments() const override { return {"move", "nudge"}; }
  std::vector<std::string> context_segments() const override { return {}; }
  CnmpPrediction generate(const std::string& segment, const Eigen::MatrixXd& observations,
                          const Eigen::VectorXd&, const Eigen::MatrixXd& query_x) override {
    starts[segment] = observations;
    const double from = observations(0, 1), to = segment == "move" ? 2.5 : 1.0;
    Eigen::MatrixXd mean(query_x.rows(), 2);
    mean.col(0) = Eigen::VectorXd::LinSpaced(query_x.rows(), from, to);
    mean.col(1).setConstant(7.0);
    return {mean, Eigen::MatrixXd::Zero(mean.rows(), 2)};
  }
  void save(const std::string&) override {}

  std::map<std::string, Eigen::MatrixXd> starts;
};

TEST(EnvironmentEvaluation, ARelativeSegmentStartsAtZeroAndRunsFromTheEffector) {
  LineTask task;
  LineExpert expert;
  LinePolicy policy;
  Rng rng(3);
  const EnvironmentEvaluation result =
      evaluate_in_environment(task, expert, nullptr, policy, 1, rng, "line");
  // The relative segment was conditioned on zero offset in column 0, the flag as it is.
  EXPECT_EQ(policy.starts.at("nudge")(0, 1), 0.0);
  EXPECT_EQ(policy.starts.at("nudge")(0, 2), 7.0);
  EXPECT_EQ(policy.starts.at("move")(0, 1), 1.0);
  // It moved 1.0 on from 2.5: the effector ends at 3.5, a success.
  ASSERT_EQ(result.evaluated.size(), 1u);
  const EvaluatedTrial& trial = result.evaluated[0];
  EXPECT_TRUE(trial.success) << trial.failure;
  EXPECT_EQ(trial.chosen_action, "forward");
  EXPECT_EQ(trial.origins.at("nudge")(0), 2.5);
  // Errors in the segments' own frames: each ends 0.5 off, linearly from 0.
  std::map<std::string, double> metrics;
  for (const auto& m : result.metrics) metrics[m.name] = m.value;
  EXPECT_NEAR(metrics.at("move_mp_error_max_m"), (0 + 0.25 + 0.5) / 3, 1e-12);
  EXPECT_NEAR(metrics.at("nudge_mp_error_max_m"), (0 + 0.25 + 0.5) / 3, 1e-12);
  EXPECT_EQ(metrics.at("decision_match_rate"), 1.0);
}

TEST(EnvironmentEvaluation, TheExecutedPathIsKeptPerSegmentUpToWhereExecutionStopped) {
  LineTask task;
  task.record_ = true;
  task.lag_ = 0.125;
  task.stop_in_ = "nudge";
  LineExpert expert;
  LinePolicy policy;
  Rng rng(3);
  const EnvironmentEvaluation result =
      evaluate_in_environment(task, expert, nullptr, policy, 1, rng, "line");
  ASSERT_EQ(result.evaluated.size(), 1u);
  const EvaluatedTrial& trial = result.evaluated[0];
  EXPECT_EQ(trial.failure, "stopped");
  // In each segment's own frame, beside what was generated: offsets for the relative one.
  Eigen::MatrixXd move(3, 2), nudge(2, 2);
  move << 0.875, 7, 1.625, 7, 2.375, 7;
  nudge << -0.125, 7, 0.375, 7;
  EXPECT_EQ(trial.executed.at("move"), move);
  EXPECT_EQ(trial.executed.at("nudge"), nudge);
  EXPECT_EQ(trial.generated.at("nudge").rows(), 3);

  LineTask silent;  // records no executed path
  LinePolicy again;
  Rng same(3);
  EXPECT_TRUE(evaluate_in_environment(silent, expert, nullptr, again, 1, same, "line")
                  .evaluated[0]
                  .executed.empty());
}

TEST(EnvironmentEvaluation, ATrialThatThrowsIsAFailedTrialWithItsReason) {
  LineTask task;
  task.throw_below_ = 2.0;  // every reset throws
  LineExpert expert;
  LinePolicy policy;
  Rng rng(3);
  const EnvironmentEvaluation result =
      evaluate_in_environment(task, expert, nullptr, policy, 2, rng, "line");
  ASSERT_EQ(result.trials.size(), 2u);
  for (const auto& trial : result.trials) {
    EXPECT_FALSE(trial.success);
    EXPECT_EQ(trial.failure, "error: cannot reset");
  }
}

// The records, metrics and tables of `trials` corridor trials on `budget` threads.
EnvironmentEvaluation replay_corridor(int budget, int trials) {
  const BudgetForScope scope(budget);
  CorridorPush environment{CorridorPushParams{}};
  CorridorExpert expert{CorridorExpertParams{}};
  PerfectContext context = corridor_context();
  ReplayingPolicy policy;
  Rng rng(23);
  return evaluate_in_environment(environment, expert, &context, policy, trials, rng, "replay");
}

TEST(EnvironmentEvaluation, TrialsOnTwoThreadsGiveTheResultsOfOne) {
  const EnvironmentEvaluation one = replay_corridor(1, 5);
  const EnvironmentEvaluation two = replay_corridor(2, 5);
  ASSERT_EQ(one.trials.size(), 5u);
  ASSERT_EQ(two.trials.size(), 5u);
  for (size_t t = 0; t < one.trials.size(); ++t) {
    EXPECT_EQ(two.trials[t].trial, static_cast<int>(t));
    EXPECT_EQ(two.trials[t].scenario, one.trials[t].scenario);
    EXPECT_EQ(two.trials[t].success, one.trials[t].success);
    EXPECT_EQ(two.trials[t].chosen_action, one.trials[t].chosen_action);
    EXPECT_EQ(two.trials[t].details, one.trials[t].details);  // contexts and outcome values
    ASSERT_EQ(two.evaluated[t].generated.size(), one.evaluated[t].generated.size());
    for (const auto& [segment, path] : one.evaluated[t].generated)
      EXPECT_EQ(two.evaluated[t].generated.at(segment), path) << segment;
    ASSERT_EQ(two.evaluated[t].executed.size(), one.evaluated[t].executed.size());
    for (const auto& [segment, path] : one.evaluated[t].executed)
      EXPECT_EQ(two.evaluated[t].executed.at(segment), path) << segment;
  }
  ASSERT_EQ(two.metrics.size(), one.metrics.size());
  for (size_t m = 0; m < one.metrics.size(); ++m) {
    EXPECT_EQ(two.metrics[m].name, one.metrics[m].name);
    EXPECT_EQ(two.metrics[m].value, one.metrics[m].value) << one.metrics[m].name;
  }
  EXPECT_EQ(two.tables, one.tables);
}

// A line task that can be cloned, whose first trial dawdles in its first segment: a later
// trial running beside it would extract before the first trial's second extraction.
class SlowLineTask : public LineTask {
 public:
  std::unique_ptr<Environment> clone() const override {
    auto copy = std::make_unique<SlowLineTask>();
    copy->failing_trial_ = failing_trial_;
    return copy;
  }
  void reset(const Scenario& scenario) override {
    if (scenario.at("index") == failing_trial_) throw std::runtime_error("cannot reset");
    LineTask::reset(scenario);
    first_trial_ = scenario.at("index") == 0.0;
  }
  double failing_trial_ = -1.0;  // clones reset every trial
  Scenario sample_scenario(Rng&) const override { return {{"throw", 1.0}, {"index", drawn_++}}; }
  std::string execute(const std::string& segment, const Eigen::MatrixXd& rows) override {
    if (first_trial_ && segment == "move")
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return LineTask::execute(segment, rows);
  }

 private:
  bool first_trial_ = false;
  mutable double drawn_ = 0.0;
};

// An extractor whose contexts are its call count: what it returns depends on the order of calls.
class CountingExtractor : public ContextExtractor {
 public:
  void fit(const std::vector<Demonstration>&, const ExtractorCache&, Rng&) override {}
  Eigen::VectorXd extract(const std::string&, const Observation&) override {
    if (calls_ == throw_at_) throw 42;  // not a std::exception: it leaves the trial's task
    return Eigen::VectorXd::Constant(1, calls_++);
  }
  int throw_at_ = -1;
  std::vector<std::string> segments() const override { return segments_; }
  bool needs_images() const override { return false; }
  std::vector<std::string> segments_{"move", "nudge"};

 private:
  int calls_ = 0;
};

// `trials` trials of the slow line task on `budget` threads, given the counting extractor's
// contexts; `failing_trial` cannot reset, and the extractor throws at call `throw_at`.
EnvironmentEvaluation evaluate_line(int budget, int trials, double failing_trial = -1.0,
                                    int throw_at = -1,
                                    std::vector<std::string> segments = {"move", "nudge"}) {
  const BudgetForScope scope(budget);
  SlowLineTask task;
  task.failing_trial_ = failing_trial;
  LineExpert expert;
  LinePolicy policy;
  CountingExtractor extractor;
  extractor.throw_at_ = throw_at;
  extractor.segments_ = std::move(segments);
  Rng rng(3);
  return evaluate_in_environment(task, expert, &extractor, policy, trials, rng, "line");
}

TEST(EnvironmentEvaluation, TheExtractorIsCalledInTrialOrderWhateverTheThreads) {
  for (const int budget : {1, 2}) {
    const EnvironmentEvaluation result = evaluate_line(budget, 4);
    ASSERT_EQ(result.evaluated.size(), 4u);
    for (int t = 0; t < 4; ++t) {
      const EvaluatedTrial& trial = result.evaluated[static_cast<size_t>(t)];
      EXPECT_EQ(trial.contexts.at("move")(0), 2 * t) << "budget " << budget << ", trial " << t;
      EXPECT_EQ(trial.contexts.at("nudge")(0), 2 * t + 1) << "budget " << budget << ", trial " << t;
      EXPECT_TRUE(trial.success) << trial.failure;
    }
  }
}

// The extractor is asked only for the segments it lists.
TEST(EnvironmentEvaluation, TheExtractorIsAskedOnlyForItsSegments) {
  for (const int budget : {1, 2}) {
    const EnvironmentEvaluation result = evaluate_line(budget, 4, -1.0, -1, {"nudge"});
    ASSERT_EQ(result.evaluated.size(), 4u);
    for (int t = 0; t < 4; ++t) {
      const EvaluatedTrial& trial = result.evaluated[static_cast<size_t>(t)];
      EXPECT_EQ(trial.contexts.count("move"), 0u);
      EXPECT_EQ(trial.contexts.at("nudge")(0), t) << "budget " << budget << ", trial " << t;
    }
  }
}

// A trial that fails in its own environment is a failed trial; the trials after it still take
// their turns.
TEST(EnvironmentEvaluation, AFailedTrialPassesItsTurnOn) {
  for (const int budget : {1, 2}) {
    const EnvironmentEvaluation result = evaluate_line(budget, 4, /*failing_trial=*/1);
    ASSERT_EQ(result.evaluated.size(), 4u);
    EXPECT_EQ(result.evaluated[1].failure, "error: cannot reset");
    EXPECT_EQ(result.evaluated[2].contexts.at("move")(0), 2) << "budget " << budget;
    EXPECT_EQ(result.evaluated[3].contexts.at("nudge")(0), 5) << "budget " << budget;
  }
}

// An error that is no std::exception leaves the evaluation (no trial hangs waiting for its turn).
TEST(EnvironmentEvaluation, AnErrorLeavingATrialStopsTheEvaluation) {
  for (const int budget : {1, 2}) {
    // The extractor throws at trial 1's first extraction.
    EXPECT_THROW(evaluate_line(budget, 6, -1.0, /*throw_at=*/2), int) << "budget " << budget;
  }
}

}  // namespace
}  // namespace corrmp
