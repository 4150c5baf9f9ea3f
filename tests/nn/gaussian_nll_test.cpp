// Tests of nn/gaussian_nll.hpp, the CNMP loss: gradients with respect to the mean and the raw
// spread against finite differences, closed-form values, and the standard-deviation floor.
#include "nn/gaussian_nll.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gradient_check.hpp"
#include "nn/activation.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

const double kHalfLogTwoPi = 0.5 * std::log(2.0 * std::acos(-1.0));

void check_gradients(const GaussianNll<double>& nll) {
  Rng rng(60);
  MatD mean = testing::random_matrix(4, 3, rng);
  MatD raw = testing::random_matrix(4, 3, rng, -1.5, 1.5);
  const MatD target = testing::random_matrix(4, 3, rng, -2.0, 2.0);
  MatD d_mean(4, 3), d_raw(4, 3);
  const double value = nll.value_and_grad(mean, raw, target, d_mean, d_raw);
  EXPECT_DOUBLE_EQ(value, nll.value(mean, raw, target));
  auto loss = [&] { return nll.value(mean, raw, target); };
  testing::expect_gradients_match(loss, {{"mean", mean.data(), d_mean.data(), mean.size()},
                                         {"raw", raw.data(), d_raw.data(), raw.size()}});
}

TEST(GaussianNllGrad, MatchesFiniteDifferencesWrtMeanAndRaw) {
  check_gradients(GaussianNll<double>());
}

TEST(GaussianNllGrad, MatchesFiniteDifferencesWithScaledSoftplus) {
  check_gradients(GaussianNll<double>(0.1, 0.9));
}

TEST(GaussianNllGrad, WorksOnColumnBlocksOfADecoderOutput) {
  // The decoder emits [mean | raw]; the loss reads both halves and writes both gradient halves.
  Rng rng(61);
  MatD out = testing::random_matrix(3, 4, rng);
  const MatD target = testing::random_matrix(3, 2, rng);
  MatD grad(3, 4);
  const GaussianNll<double> nll;
  nll.value_and_grad(out.leftCols(2), out.rightCols(2), target, grad.leftCols(2),
                     grad.rightCols(2));
  auto loss = [&] { return nll.value(out.leftCols(2), out.rightCols(2), target); };
  testing::expect_gradients_match(loss, {{"output", out.data(), grad.data(), out.size()}});
}

TEST(GaussianNll, ValueMatchesClosedForm) {
  const GaussianNll<double> nll(0.01, 1.0);
  // softplus(raw) = 0.99 -> sigma = 1.
  const double raw_for_unit_std = std::log(std::expm1(0.99));
  MatD mean(1, 2), raw(1, 2), target(1, 2);
  mean << 0.5, -1.0;
  raw << raw_for_unit_std, raw_for_unit_std;
  target << 0.5, 1.0;  // z = 0 and z = 2
  EXPECT_NEAR(nll.value(mean, raw, target), kHalfLogTwoPi + 0.5 * (0.0 + 0.5 * 4.0), 1e-12);
}

TEST(GaussianNll, StdHasConfigurableFloor) {
  const GaussianNll<double> nll(0.05, 1.0);
  EXPECT_NEAR(nll.std_from_raw(-60.0), 0.05, 1e-15);
  EXPECT_DOUBLE_EQ(nll.std_from_raw(0.0), 0.05 + std::log(2.0));
  const GaussianNll<double> cnmp_style(0.1, 0.9);
  EXPECT_DOUBLE_EQ(cnmp_style.std_from_raw(2.0), 0.1 + 0.9 * softplus(2.0));
  EXPECT_THROW(GaussianNll<double>(0.0), std::invalid_argument);
}

TEST(GaussianNll, FloatAgreesWithDouble) {
  Rng rng(62);
  const MatD mean = testing::random_matrix(5, 3, rng);
  const MatD raw = testing::random_matrix(5, 3, rng);
  const MatD target = testing::random_matrix(5, 3, rng);
  const double d = GaussianNll<double>().value(mean, raw, target);
  const float f =
      GaussianNll<float>().value(mean.cast<float>(), raw.cast<float>(), target.cast<float>());
  EXPECT_NEAR(f, d, 1e-5 * std::abs(d));
}

TEST(GaussianNll, RejectsMismatchedShapes) {
  const GaussianNll<double> nll;
  EXPECT_THROW(nll.value(MatD(2, 2), MatD(2, 3), MatD(2, 2)), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp::nn
