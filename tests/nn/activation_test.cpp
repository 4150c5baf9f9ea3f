// Tests of nn/activation.hpp: every activation's backward pass against finite differences,
// in-place use, and the numerically stable scalar sigmoid / softplus.
#include "nn/activation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

template <class Activation>
class ActivationGrad : public ::testing::Test {};

using Activations = ::testing::Types<Relu<double>, LeakyRelu<double>, Sigmoid<double>, Tanh<double>,
                                     Softplus<double>>;
TYPED_TEST_SUITE(ActivationGrad, Activations);

TYPED_TEST(ActivationGrad, MatchesFiniteDifferences) {
  const TypeParam f;
  Rng rng(10);
  MatD x = 2.0 * testing::random_matrix_away_from_zero(4, 6, rng, 0.05);
  const MatD r = testing::random_matrix(4, 6, rng);
  MatD y(4, 6), dx(4, 6);
  f.forward(x, y);
  f.backward(y, r, dx);
  auto loss = [&] {
    MatD out(4, 6);
    f.forward(x, out);
    return testing::weighted_sum(out, r);
  };
  testing::expect_gradients_match(loss, {{"x", x.data(), dx.data(), x.size()}});
}

TYPED_TEST(ActivationGrad, InPlaceMatchesOutOfPlace) {
  const TypeParam f;
  Rng rng(11);
  const MatD x = 3.0 * testing::random_matrix(3, 5, rng);
  const MatD dy = testing::random_matrix(3, 5, rng);
  MatD y(3, 5), dx(3, 5);
  f.forward(x, y);
  f.backward(y, dy, dx);
  MatD buffer = x, grad = dy;
  f.forward(buffer, buffer);
  f.backward(buffer, grad, grad);
  EXPECT_TRUE(buffer.isApprox(y, 1e-15));
  EXPECT_TRUE(grad.isApprox(dx, 1e-15));
}

TEST(Activation, ForwardValues) {
  MatD x(1, 3);
  x << -2.0, 0.0, 3.0;
  MatD y(1, 3);
  Relu<double>().forward(x, y);
  EXPECT_EQ(y, (MatD(1, 3) << 0.0, 0.0, 3.0).finished());
  LeakyRelu<double>(0.1).forward(x, y);
  EXPECT_TRUE(y.isApprox((MatD(1, 3) << -0.2, 0.0, 3.0).finished()));
  Sigmoid<double>().forward(x, y);
  EXPECT_DOUBLE_EQ(y(0, 1), 0.5);
  EXPECT_DOUBLE_EQ(y(0, 2), 1.0 / (1.0 + std::exp(-3.0)));
  Tanh<double>().forward(x, y);
  EXPECT_DOUBLE_EQ(y(0, 0), std::tanh(-2.0));
  Softplus<double>().forward(x, y);
  EXPECT_DOUBLE_EQ(y(0, 1), std::log(2.0));
  EXPECT_DOUBLE_EQ(y(0, 2), std::log1p(std::exp(3.0)));
}

// The float sigmoid (Eigen's vectorised logistic, used in place by the autoencoder's output
// layer) against the scalar formula in double, every 0.001 from -20 to 20 and at +-1e30: always
// in [0, 1] and within 2 float ulps of 1 (measured: 0.97). Outputs around exp(-9), where Eigen's
// fit ends, are accurate only to 1e-3 of themselves (measured: 8.2e-4 at -8.87), so the relative
// bound is 2e-3, checked down to the smallest normal float.
TEST(Activation, FloatSigmoidIsAccurateOverTheWholeRange) {
  const Index n = 40003;
  Mat<float> x(1, n);
  for (Index i = 0; i + 2 < n; ++i) x(0, i) = -20.0f + 0.001f * static_cast<float>(i);
  x(0, n - 2) = -1e30f;
  x(0, n - 1) = 1e30f;
  Mat<float> y = x;
  Sigmoid<float>().forward(y, y);  // in place
  double largest_absolute = 0.0, largest_relative = 0.0;
  for (Index i = 0; i < n; ++i) {
    const double expected = sigmoid(static_cast<double>(x(0, i)));
    ASSERT_TRUE(y(0, i) >= 0.0f && y(0, i) <= 1.0f) << "x = " << x(0, i);
    const double error = std::abs(static_cast<double>(y(0, i)) - expected);
    largest_absolute = std::max(largest_absolute, error);
    if (expected >= std::numeric_limits<float>::min())  // normal floats
      largest_relative = std::max(largest_relative, error / expected);
  }
  EXPECT_LE(largest_absolute, 2.0 * std::numeric_limits<float>::epsilon());
  EXPECT_LE(largest_relative, 2e-3);
}

TEST(Activation, LeakyReluRejectsNegativeSlope) {
  EXPECT_THROW(LeakyRelu<double>(-0.5), std::invalid_argument);
}

TEST(Activation, ScalarFunctionsAreStableForLargeArguments) {
  EXPECT_EQ(sigmoid(-1000.0), 0.0);
  EXPECT_EQ(sigmoid(1000.0), 1.0);
  EXPECT_DOUBLE_EQ(softplus(1000.0), 1000.0);
  EXPECT_DOUBLE_EQ(softplus(-50.0), std::exp(-50.0));
  EXPECT_FALSE(std::isnan(softplus(-1000.0f)));
  EXPECT_DOUBLE_EQ(softplus(0.3), std::log1p(std::exp(0.3)));
  EXPECT_DOUBLE_EQ(sigmoid(0.3), 1.0 / (1.0 + std::exp(-0.3)));
}

TEST(ActivationGrad, SoftplusDerivativeIsSigmoid) {
  MatD x(1, 4);
  x << -30.0, -1.0, 0.5, 20.0;
  MatD y(1, 4), dx(1, 4);
  Softplus<double>().forward(x, y);
  Softplus<double>().backward(y, MatD::Ones(1, 4), dx);
  for (Index j = 0; j < 4; ++j) EXPECT_NEAR(dx(0, j), sigmoid(x(0, j)), 1e-14 + 1e-12 * dx(0, j));
}

}  // namespace
}  // namespace corrmp::nn
