// Tests of CNMP training: learning a context-parameterised family of curves
// to a set error on contexts not trained on, and determinism.
#include "cnmp/cnmp_trainer.hpp"

#include <gtest/gtest.h>

#include "cnmp/curve_family.hpp"
#include "core/thread_budget.hpp"
#include "nn/gemm.hpp"

namespace corrmp {
namespace {

std::vector<CnmpTrajectory> curves(const std::vector<Demonstration>& demos) {
  std::vector<CnmpTrajectory> out;
  for (const auto& d : demos) {
    const auto& s = d.segments.front();
    out.push_back({s.x, s.y, s.context});
  }
  return out;
}

struct Fixture {
  std::vector<CnmpTrajectory> train, validation;
  Fixture() {
    CurveFamilyParams p;
    p.train = 20;
    p.validation = 10;
    CurveFamily family(p);
    Rng rng(2);
    const DemonstrationSplit split = family.collect(nullptr, rng);
    train = curves(split.train);
    validation = curves(split.validation);
  }
};

CnmpArchitecture curve_architecture() {
  CnmpArchitecture a;
  a.d_context = 1;
  a.width = 32;
  return a;
}

CnmpTrainingParams quick_training() {
  CnmpTrainingParams p;
  p.updates = 6000;
  p.batch_size = 8;
  p.max_targets = 5;
  p.learning_rate = 1e-3;
  p.validate_every = 500;
  return p;
}

TEST(CnmpTrainer, LearnsACurveFamilyAndGeneralisesToUnseenContexts) {
  const Fixture data;
  CnmpModel model(curve_architecture(), 1);
  const PredictionError untrained = prediction_error(model, data.validation);
  Rng rng(4);
  const TrainingReport report =
      train_cnmp(model, data.train, data.validation, quick_training(), rng, "curves");
  const PredictionError trained = prediction_error(model, data.validation);
  // The curves span about 1.5 in y; unseen contexts must be predicted closely.
  EXPECT_LT(trained.mean, 0.03) << "untrained " << untrained.mean;
  EXPECT_LT(trained.max, 0.08);
  EXPECT_LT(trained.mean, untrained.mean / 10);
  EXPECT_DOUBLE_EQ(trained.mean, report.best_validation.mean);
  EXPECT_GT(report.best_update, 0);
}

TEST(CnmpTrainer, SameSeedGivesIdenticalWeights) {
  const Fixture data;
  CnmpTrainingParams p = quick_training();
  p.updates = 300;
  auto train = [&] {
    CnmpModel model(curve_architecture(), 9);
    Rng rng(9);
    train_cnmp(model, data.train, data.validation, p, rng, "determinism");
    std::vector<float> weights;
    for (const auto& param : model.network().parameters()) {
      weights.insert(weights.end(), param.value, param.value + param.size());
    }
    return weights;
  };
  const auto first = train();
  EXPECT_EQ(first, train());
  CnmpModel other(curve_architecture(), 10);
  EXPECT_NE(other.network().parameters().front().values()(0),
            CnmpModel(curve_architecture(), 9).network().parameters().front().values()(0));
}

// A network as wide as the monolithic baseline's trains its updates and validations on two
// workers when the thread budget allows (cnmp/parallel_cnmp_step.hpp): the same weights, curve
// and best checkpoint as on one.
TEST(CnmpTrainer, AWideNetworkTrainsIdenticallyOnOneAndTwoThreads) {
  const Fixture data;
  CnmpArchitecture a = curve_architecture();
  a.width = 223;
  CnmpTrainingParams p = quick_training();
  p.updates = 120;
  p.validate_every = 40;
  if (!nn::gemm_float_split_exact()) GTEST_SKIP() << "float products run on Eigen in this build";
  struct RestoreBudget {
    int saved = thread_budget();
    ~RestoreBudget() { set_thread_budget(saved); }
  } restore;
  std::vector<std::vector<Eigen::VectorXf>> weights;
  std::vector<TrainingReport> reports;
  for (int threads : {1, 2}) {
    set_thread_budget(threads);
    CnmpModel model(a, 1);
    ASSERT_GE(model.network().parameter_count(), 200000);
    Rng rng(4);
    reports.push_back(train_cnmp(model, data.train, data.validation, p, rng, "wide"));
    weights.emplace_back();
    for (const auto& param : model.network().parameters()) weights.back().push_back(param.values());
  }
  EXPECT_EQ(reports[0].team_updates, 0);
  EXPECT_GT(reports[1].team_updates, 0);  // the two-thread run did use the team
  EXPECT_EQ(reports[0].best_update, reports[1].best_update);
  ASSERT_EQ(reports[0].curve.size(), reports[1].curve.size());
  for (size_t i = 0; i < reports[0].curve.size(); ++i) {
    EXPECT_EQ(reports[0].curve[i].loss, reports[1].curve[i].loss);
    EXPECT_EQ(reports[0].curve[i].validation_mean, reports[1].curve[i].validation_mean);
    EXPECT_EQ(reports[0].curve[i].validation_max, reports[1].curve[i].validation_max);
  }
  for (size_t k = 0; k < weights[0].size(); ++k)
    EXPECT_TRUE((weights[0][k].array() == weights[1][k].array()).all()) << "parameter " << k;
}

TEST(CnmpTrainer, RejectsTrajectoriesOfTheWrongShape) {
  CnmpModel model(curve_architecture(), 1);
  std::vector<CnmpTrajectory> bad{
      {Eigen::MatrixXd::Zero(5, 1), Eigen::MatrixXd::Zero(5, 2), Eigen::VectorXd::Zero(1)}};
  Rng rng(1);
  EXPECT_THROW(train_cnmp(model, bad, {}, quick_training(), rng, "bad"), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp

namespace corrmp {
namespace {

TEST(CnmpTrainer, TheLearningRateIsConstantOrFollowsACosineDown) {
  CnmpTrainingParams p;
  p.updates = 1000;
  p.learning_rate = 1e-3;
  EXPECT_DOUBLE_EQ(scheduled_learning_rate(p, 1), 1e-3);
  EXPECT_DOUBLE_EQ(scheduled_learning_rate(p, 1000), 1e-3);
  p.final_learning_rate = 1e-4;
  EXPECT_DOUBLE_EQ(scheduled_learning_rate(p, 1), 1e-3);
  EXPECT_NEAR(scheduled_learning_rate(p, 501), 5.5e-4, 1e-12);
  EXPECT_NEAR(scheduled_learning_rate(p, 1000), 1e-4, 1e-8);
  for (int64_t u = 2; u <= 1000; ++u) {
    EXPECT_LE(scheduled_learning_rate(p, u), scheduled_learning_rate(p, u - 1));
  }
}

}  // namespace
}  // namespace corrmp
