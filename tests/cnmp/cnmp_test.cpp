// Tests of the CNMP: gradients of the whole model against finite differences, its
// prediction against the definition computed with plain layers, no allocation once warmed
// up, batches refused, parameter counting and budgets, model-file round trips.
#include "cnmp/cnmp.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "nn/gradient_check.hpp"

#include "cnmp/cnmp_model.hpp"
#include "config/test_files.hpp"
#include "support/allocation_counter.hpp"

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using MatD = nn::Mat<double>;

CnmpArchitecture small_architecture() {
  CnmpArchitecture a;
  a.d_x = 2;
  a.d_y = 3;
  a.d_context = 2;
  a.encoder_layers = 2;
  a.decoder_layers = 3;
  a.width = 6;
  a.min_std = 0.05;
  return a;
}

// The gradients of train_step against finite differences, for two tasks with different counts.
void expect_train_step_gradients_match(const CnmpArchitecture& a) {
  nn::Rng rng(5);
  Cnmp<double> model(a, rng);
  const CnmpBatchCounts counts{{2, 3}, {1, 2}};  // two tasks, different counts
  const MatD observations = nn::testing::random_matrix(5, a.d_x + a.d_y, rng);
  const MatD contexts = nn::testing::random_matrix(2, a.d_context, rng);
  const MatD target_x = nn::testing::random_matrix(3, a.d_x, rng);
  const MatD target_y = nn::testing::random_matrix(3, a.d_y, rng);

  auto params = model.parameters();
  nn::zero_grad(params);
  model.train_step(observations, contexts, target_x, target_y, counts);
  // train_step accumulates into the gradients, so keep the analytic ones apart.
  std::vector<Eigen::VectorXd> analytic;
  std::vector<nn::testing::GradientCase> cases;
  for (const auto& p : params) analytic.push_back(p.grads());
  for (size_t k = 0; k < params.size(); ++k) {
    cases.push_back({params[k].name, params[k].value, analytic[k].data(), params[k].size()});
  }
  nn::testing::expect_gradients_match(
      [&] { return model.train_step(observations, contexts, target_x, target_y, counts); }, cases);
}

TEST(CnmpGrad, TrainStepMatchesFiniteDifferencesWithVariableCounts) {
  expect_train_step_gradients_match(small_architecture());
}

TEST(CnmpGrad, ADecoderOfOneLayerWithoutContextMatchesFiniteDifferences) {
  CnmpArchitecture a = small_architecture();
  a.d_context = 0;
  a.decoder_layers = 1;
  expect_train_step_gradients_match(a);
}

// The CNMP's definition computed with plain layers: the mean encoding r, then the decoder on
// the rows [r, c, x_q], every target repeating r. The plain layers drawn from the same seed
// have the model's weights under the model's names (those of its model files).
TEST(Cnmp, PredictsWhatTheDecoderGivesForTheMeanEncodingRepeatedPerQuery) {
  const CnmpArchitecture a = small_architecture();
  nn::Rng rng(5), reference_rng(5);
  Cnmp<double> model(a, rng);
  nn::Mlp<double> encoder({a.d_x + a.d_y, a.width, a.width}, reference_rng);
  nn::Mlp<double> decoder({a.width + a.d_context + a.d_x, a.width, a.width, 2 * a.d_y},
                          reference_rng);
  auto reference = encoder.parameters("encoder.");
  nn::append_parameters(reference, decoder.parameters("decoder."));
  const auto params = model.parameters();
  ASSERT_EQ(reference.size(), params.size());
  for (size_t k = 0; k < params.size(); ++k) {
    ASSERT_EQ(reference[k].name, params[k].name);
    ASSERT_EQ(reference[k].shape, params[k].shape);
    EXPECT_EQ(reference[k].values(), params[k].values()) << params[k].name;
  }
  const MatD observations = nn::testing::random_matrix(3, a.d_x + a.d_y, rng);
  const MatD context = nn::testing::random_matrix(1, a.d_context, rng);
  const MatD query = nn::testing::random_matrix(4, a.d_x, rng);
  MatD mean, std;
  model.predict(observations, context, query, mean, std);

  const Eigen::RowVectorXd r = encoder.forward(observations).colwise().mean();
  MatD rows(4, a.width + a.d_context + a.d_x);
  for (int t = 0; t < 4; ++t) rows.row(t) << r, context.row(0), query.row(t);
  const MatD out = decoder.forward(rows);
  EXPECT_LT((mean - out.leftCols(a.d_y)).cwiseAbs().maxCoeff(), 1e-12);
  MatD expected_std(4, a.d_y);
  nn::GaussianNll<double>(a.min_std).std_from_raw(out.rightCols(a.d_y), expected_std);
  EXPECT_LT((std - expected_std).cwiseAbs().maxCoeff(), 1e-12);
}

// Once warmed up with its largest batch, a training step allocates nothing, also for smaller
// batches (counted by tests/support/allocation_counter.hpp).
TEST(Cnmp, AWarmedUpTrainingStepDoesNotAllocate) {
  if (!testing::kAllocationCounting) GTEST_SKIP() << "allocation counting is off under sanitizers";
  const CnmpArchitecture a = small_architecture();
  nn::Rng rng(5);
  Cnmp<float> model(a, rng);
  std::vector<CnmpBatchCounts> batches{{{3, 2, 4}, {5, 1, 3}}, {{1, 2}, {2, 0}}, {{2}, {1}}};
  std::vector<nn::Mat<float>> inputs;  // observations, contexts, target x, target y per batch
  for (const CnmpBatchCounts& c : batches) {
    const auto sum = [](const std::vector<int>& v) {
      return std::accumulate(v.begin(), v.end(), 0);
    };
    const auto tasks = static_cast<nn::Index>(c.observations.size());
    inputs.push_back(nn::Mat<float>::Random(sum(c.observations), a.d_x + a.d_y));
    inputs.push_back(nn::Mat<float>::Random(tasks, a.d_context));
    inputs.push_back(nn::Mat<float>::Random(sum(c.targets), a.d_x));
    inputs.push_back(nn::Mat<float>::Random(sum(c.targets), a.d_y));
  }
  const auto step = [&](size_t b) {
    return model.train_step(inputs[4 * b], inputs[4 * b + 1], inputs[4 * b + 2], inputs[4 * b + 3],
                            batches[b]);
  };
  step(0);  // warm-up with the largest batch
  float loss = 0.0f;
  const long allocations = testing::count_allocations([&] {
    for (size_t b = 0; b < batches.size(); ++b) loss += step(b);
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_TRUE(std::isfinite(loss));
}

TEST(Cnmp, ATrainingBatchThatDoesNotMatchItsCountsIsRefused) {
  const CnmpArchitecture a = small_architecture();
  nn::Rng rng(5);
  Cnmp<double> model(a, rng);
  const CnmpBatchCounts counts{{2, 3}, {1, 2}};
  const MatD contexts = MatD::Zero(2, a.d_context);
  const MatD target_y = MatD::Zero(3, a.d_y);
  // 4 observation rows for counts adding up to 5, then rows of the wrong width.
  EXPECT_THROW(model.train_step(MatD::Zero(4, a.d_x + a.d_y), contexts, MatD::Zero(3, a.d_x),
                                target_y, counts),
               std::invalid_argument);
  EXPECT_THROW(model.train_step(MatD::Zero(5, a.d_x + a.d_y + 1), contexts, MatD::Zero(3, a.d_x),
                                target_y, counts),
               std::invalid_argument);
  // A task without observations would average nothing.
  EXPECT_THROW(model.train_step(MatD::Zero(5, a.d_x + a.d_y), contexts, MatD::Zero(3, a.d_x),
                                target_y, CnmpBatchCounts{{0, 5}, {1, 2}}),
               std::invalid_argument);
  EXPECT_NO_THROW(model.train_step(MatD::Zero(5, a.d_x + a.d_y), contexts, MatD::Zero(3, a.d_x),
                                   target_y, counts));
}

TEST(CnmpArchitecture, ParameterCountMatchesTheNetworkAndBudgetsPickTheClosestWidth) {
  CnmpArchitecture a;
  a.d_x = 1;
  a.d_y = 3;
  a.d_context = 1;
  nn::Rng init(1);
  Cnmp<float> paper(a, init);
  EXPECT_EQ(cnmp_parameter_count(a), paper.parameter_count());
  // Encoder 4->128->128->128, decoder 130->128->128->128->6.
  EXPECT_EQ(cnmp_parameter_count(a), (4 * 128 + 128) + 2 * (128 * 128 + 128) + (130 * 128 + 128) +
                                         2 * (128 * 128 + 128) + (128 * 6 + 6));
  const int64_t three_networks = 3 * cnmp_parameter_count(a);
  const int width = width_for_parameter_budget(a, three_networks);
  CnmpArchitecture wide = a;
  wide.width = width;
  const int64_t gap = std::llabs(cnmp_parameter_count(wide) - three_networks);
  for (int other : {width - 1, width + 1}) {
    wide.width = other;
    EXPECT_GE(std::llabs(cnmp_parameter_count(wide) - three_networks), gap);
  }
  EXPECT_GT(width, 128);
}

TEST(CnmpModel, SaveAndLoadGiveIdenticalPredictions) {
  testing::TempDir dir;
  CnmpArchitecture a = small_architecture();
  CnmpModel model(a, 3);
  model.y_normaliser = {Eigen::RowVector3d(0.1, 0.2, 0.3), Eigen::RowVector3d(2.0, 3.0, 4.0)};
  model.context_normaliser = {Eigen::RowVector2d(1.0, -1.0), Eigen::RowVector2d(0.5, 0.25)};
  Eigen::MatrixXd observations(2, 5);
  observations << 0.0, 0.1, 1.0, 2.0, 3.0, 0.5, 0.2, 1.5, 2.5, 3.5;
  const Eigen::Vector2d context(0.3, -0.7);
  const Eigen::MatrixXd query = Eigen::MatrixXd::Random(7, 2);
  const CnmpPrediction before = model.predict(observations, context, query);
  model.save(dir.file("m.cnmp"));
  const auto loaded = CnmpModel::load(dir.file("m.cnmp"));
  const CnmpPrediction after = loaded->predict(observations, context, query);
  EXPECT_EQ(before.mean, after.mean);
  EXPECT_EQ(before.std, after.std);
  EXPECT_TRUE((after.std.array() > 0).all());
}

TEST(CnmpModel, LoadingAMismatchedOrForeignFileFails) {
  testing::TempDir dir;
  CnmpModel model(small_architecture(), 3);
  model.save(dir.file("m.cnmp"));
  nn::ModelFile file = nn::ModelFile::read(dir.file("m.cnmp"));
  CnmpArchitecture other = small_architecture();
  other.width = 7;
  nn::Rng init(1);
  Cnmp<float> wrong(other, init);
  EXPECT_THAT([&] { wrong.load_from(file); },
              ThrowsMessage<std::runtime_error>(HasSubstr("differs from the expected")));
  nn::ModelFile foreign;
  foreign.hyper["model"] = "autoencoder";
  foreign.write(dir.file("ae.bin"));
  EXPECT_THROW(CnmpModel::load(dir.file("ae.bin")), std::runtime_error);
}

TEST(CnmpModel, PredictRejectsBadShapes) {
  CnmpModel model(small_architecture(), 3);
  const Eigen::MatrixXd query = Eigen::MatrixXd::Zero(3, 2);
  EXPECT_THROW(model.predict(Eigen::MatrixXd::Zero(1, 4), Eigen::Vector2d::Zero(), query),
               std::invalid_argument);
  EXPECT_THROW(model.predict(Eigen::MatrixXd::Zero(1, 5), Eigen::Vector3d::Zero(), query),
               std::invalid_argument);
  EXPECT_THROW(model.predict(Eigen::MatrixXd::Zero(0, 5), Eigen::Vector2d::Zero(), query),
               std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
