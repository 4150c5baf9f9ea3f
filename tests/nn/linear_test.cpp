// Tests of nn/linear.hpp: gradients against finite differences, accumulation, PyTorch-style
// initialisation and its determinism.
#include "nn/linear.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

TEST(LinearGrad, MatchesFiniteDifferences) {
  Rng rng(1);
  Linear<double> layer(4, 3, rng);
  MatD x = testing::random_matrix(5, 4, rng);
  const MatD r = testing::random_matrix(5, 3, rng);
  auto params = layer.parameters();
  zero_grad(params);
  MatD dx(5, 4);
  layer.backward(x, r, dx);
  auto loss = [&] {
    MatD y(5, 3);
    layer.forward(x, y);
    return testing::weighted_sum(y, r);
  };
  testing::expect_gradients_match(loss, testing::cases_for("x", x, dx, params));
}

TEST(LinearGrad, AccumulatesAcrossBackwardCallsUntilZeroGrad) {
  Rng rng(2);
  Linear<double> layer(3, 2, rng);
  const MatD x = testing::random_matrix(4, 3, rng);
  const MatD dy = testing::random_matrix(4, 2, rng);
  auto params = layer.parameters();
  zero_grad(params);
  layer.accumulate_param_grad(x, dy);
  const MatD once = layer.weight_grad();
  const Eigen::RowVectorXd bias_once = layer.bias_grad();
  layer.accumulate_param_grad(x, dy);
  EXPECT_TRUE(layer.weight_grad().isApprox(2.0 * once));
  EXPECT_TRUE(layer.bias_grad().isApprox(2.0 * bias_once));
  zero_grad(params);
  EXPECT_EQ(layer.weight_grad().norm(), 0.0);
  EXPECT_EQ(layer.bias_grad().norm(), 0.0);
}

TEST(Linear, ForwardComputesAffineMap) {
  Rng rng(3);
  Linear<double> layer(2, 2, rng);
  layer.weight() << 1.0, 2.0, -1.0, 0.5;
  layer.bias() << 0.25, -3.0;
  MatD x(1, 2);
  x << 2.0, -4.0;
  MatD y(1, 2);
  layer.forward(x, y);
  EXPECT_DOUBLE_EQ(y(0, 0), 2.0 - 8.0 + 0.25);
  EXPECT_DOUBLE_EQ(y(0, 1), -2.0 - 2.0 - 3.0);
}

TEST(Linear, RejectsWrongShapes) {
  Rng rng(4);
  Linear<double> layer(3, 2, rng);
  MatD x(2, 4), y(2, 2), bad_y(2, 3);
  EXPECT_THROW(layer.forward(x, y), std::invalid_argument);
  MatD good_x(2, 3);
  EXPECT_THROW(layer.forward(good_x, bad_y), std::invalid_argument);
}

TEST(LinearInit, WeightsAndBiasWithinPyTorchBound) {
  Rng rng(5);
  const Index in = 16;
  Linear<float> layer(in, 64, rng);
  const float bound = 1.0f / std::sqrt(static_cast<float>(in));
  EXPECT_LE(layer.weight().cwiseAbs().maxCoeff(), bound);
  EXPECT_LE(layer.bias().cwiseAbs().maxCoeff(), bound);
  // The draws spread over the interval rather than collapsing to a constant.
  EXPECT_GT(layer.weight().maxCoeff(), 0.8f * bound);
  EXPECT_LT(layer.weight().minCoeff(), -0.8f * bound);
  EXPECT_NEAR(layer.weight().mean(), 0.0f, 0.1f * bound);
}

TEST(LinearInit, SameSeedGivesIdenticalWeights) {
  Rng a(42), b(42), c(43);
  Linear<float> la(8, 5, a), lb(8, 5, b), lc(8, 5, c);
  EXPECT_EQ(la.weight(), lb.weight());
  EXPECT_EQ(la.bias(), lb.bias());
  EXPECT_NE(la.weight(), lc.weight());
}

TEST(Linear, ParametersExposeValuesGradientsAndShapes) {
  Rng rng(6);
  Linear<double> layer(3, 2, rng);
  auto params = layer.parameters("fc.");
  ASSERT_EQ(params.size(), 2u);
  EXPECT_EQ(params[0].name, "fc.weight");
  EXPECT_EQ(params[0].shape, (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(params[1].name, "fc.bias");
  EXPECT_EQ(params[1].shape, (std::vector<std::int64_t>{2}));
  params[0].values()[1] = 7.0;  // row 0, column 1
  EXPECT_EQ(layer.weight()(0, 1), 7.0);
  EXPECT_EQ(count_parameters(params), layer.num_parameters());
  EXPECT_EQ(layer.num_parameters(), 8);
}

}  // namespace
}  // namespace corrmp::nn
