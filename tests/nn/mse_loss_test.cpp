// Tests of nn/mse_loss.hpp: gradient against finite differences and known values.
#include "nn/mse_loss.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

TEST(MseLossGrad, MatchesFiniteDifferences) {
  Rng rng(70);
  MatD prediction = testing::random_matrix(3, 5, rng);
  const MatD target = testing::random_matrix(3, 5, rng);
  MatD grad(3, 5);
  const MseLoss<double> mse;
  const double value = mse.value_and_grad(prediction, target, grad);
  EXPECT_DOUBLE_EQ(value, mse.value(prediction, target));
  auto loss = [&] { return mse.value(prediction, target); };
  testing::expect_gradients_match(
      loss, {{"prediction", prediction.data(), grad.data(), prediction.size()}});
}

TEST(MseLoss, KnownValue) {
  MatD p(2, 2), y(2, 2);
  p << 1, 2, 3, 4;
  y << 1, 0, 3, 1;
  EXPECT_DOUBLE_EQ(MseLoss<double>().value(p, y), (0.0 + 4.0 + 0.0 + 9.0) / 4.0);
  EXPECT_THROW(MseLoss<double>().value(p, MatD(2, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp::nn
