// Tests of nn/adam.hpp: two hand-computed PyTorch-Adam steps (with and without L2 weight
// decay), convergence on a quadratic, zero_grad, option validation, and steps split into ranges
// (as the data-parallel autoencoder trainer runs them on several threads).
#include "nn/adam.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "nn/parameter.hpp"

namespace corrmp::nn {
namespace {

// A single scalar parameter with its gradient.
struct Scalar {
  double value;
  double grad = 0.0;
  std::vector<Parameter<double>> params() { return {{"p", {1}, &value, &grad}}; }
};

TEST(Adam, MatchesHandComputedTwoSteps) {
  // lr 0.1, betas (0.9, 0.999), eps 1e-8, p0 = 1, gradients 0.5 then -0.2.
  // Step 1: m = 0.05, v = 0.00025, m_hat = 0.5, v_hat = 0.25,
  //         p1 = 1 - 0.1 * 0.5 / (0.5 + 1e-8) = 0.900000002
  // Step 2: m = 0.025, v = 0.00028975, m_hat = 0.025 / 0.19, v_hat = 0.00028975 / 0.001999,
  //         p2 = p1 - 0.1 * m_hat / (sqrt(v_hat) + 1e-8) = 0.8654394181165108
  Scalar p{1.0};
  AdamOptions options;
  options.learning_rate = 0.1;
  Adam<double> adam(p.params(), options);
  p.grad = 0.5;
  adam.step();
  EXPECT_NEAR(p.value, 0.900000002, 1e-15);
  p.grad = -0.2;
  adam.step();
  EXPECT_NEAR(p.value, 0.8654394181165108, 1e-15);
  EXPECT_EQ(adam.step_count(), 2);
}

TEST(Adam, WeightDecayIsL2AddedToTheGradient) {
  // lr 0.01, weight_decay 0.1, p0 = 2: effective gradients 0 + 0.1 * 2 = 0.2, then
  // 0.3 + 0.1 * 1.9900000005. Hand computation gives 1.9900000005 and 1.980600539653467.
  Scalar p{2.0};
  AdamOptions options;
  options.learning_rate = 0.01;
  options.weight_decay = 0.1;
  Adam<double> adam(p.params(), options);
  p.grad = 0.0;
  adam.step();
  EXPECT_NEAR(p.value, 1.9900000005, 1e-15);
  p.grad = 0.3;
  adam.step();
  EXPECT_NEAR(p.value, 1.980600539653467, 1e-15);
}

TEST(Adam, MinimisesAQuadratic) {
  // f(p) = 0.5 sum a_i (p_i - c_i)^2 over a parameter vector split into two tensors.
  Eigen::Vector3d a(1.0, 10.0, 0.1), c(3.0, -2.0, 0.5);
  Eigen::Vector2d p1(0.0, 0.0), g1;
  Eigen::Matrix<double, 1, 1> p2(5.0), g2;
  std::vector<Parameter<double>> params{{"p1", {2}, p1.data(), g1.data()},
                                        {"p2", {1}, p2.data(), g2.data()}};
  AdamOptions options;
  options.learning_rate = 0.05;
  Adam<double> adam(params, options);
  auto value = [&] {
    const Eigen::Vector3d p(p1[0], p1[1], p2[0]);
    return 0.5 * (a.array() * (p - c).array().square()).sum();
  };
  const double initial = value();
  for (int step = 0; step < 3000; ++step) {
    adam.zero_grad();
    g1 = (a.head<2>().array() * (p1 - c.head<2>()).array()).matrix();
    g2[0] = a[2] * (p2[0] - c[2]);
    adam.step();
  }
  EXPECT_LT(value(), 1e-8 * initial);
  EXPECT_NEAR(p1[0], c[0], 1e-3);
  EXPECT_NEAR(p1[1], c[1], 1e-3);
  EXPECT_NEAR(p2[0], c[2], 1e-3);
}

TEST(Adam, ZeroGradClearsAllGradients) {
  Eigen::Vector3f value(1, 2, 3), grad(4, 5, 6);
  Adam<float> adam({{"v", {3}, value.data(), grad.data()}}, AdamOptions{});
  adam.zero_grad();
  EXPECT_EQ(grad, Eigen::Vector3f::Zero());
}

// Updating a step's entries in ranges on kRangeAlignment boundaries, in any order, gives exactly
// step()'s result.
TEST(Adam, AlignedRangesOfAStepGiveExactlyTheStep) {
  constexpr Index kAlign = Adam<float>::kRangeAlignment;
  const Index sizes[] = {2 * kAlign + 904, 37};
  std::vector<Eigen::VectorXf> values, grads;
  for (Index size : sizes) {
    values.push_back(Eigen::VectorXf::Random(size));
    grads.push_back(Eigen::VectorXf::Random(size));
  }
  std::vector<Eigen::VectorXf> split_values = values, split_grads = grads;
  std::vector<Parameter<float>> whole, split;
  for (size_t k = 0; k < values.size(); ++k) {
    whole.push_back({"p" + std::to_string(k), {sizes[k]}, values[k].data(), grads[k].data()});
    split.push_back(
        {"p" + std::to_string(k), {sizes[k]}, split_values[k].data(), split_grads[k].data()});
  }
  AdamOptions options;
  options.learning_rate = 0.01;
  options.weight_decay = 0.1;
  Adam<float> a(whole, options), b(split, options);
  for (int step = 0; step < 3; ++step) {
    a.step();
    b.begin_step();
    b.update_range(1, 0, 37);
    b.update_range(0, 2 * kAlign, sizes[0]);  // the ranges out of order
    b.update_range(0, 0, kAlign);
    b.update_range(0, kAlign, 2 * kAlign);
    for (size_t k = 0; k < values.size(); ++k) {
      grads[k] *= -0.5f;
      split_grads[k] *= -0.5f;
    }
  }
  EXPECT_EQ(b.step_count(), 3);
  for (size_t k = 0; k < values.size(); ++k) EXPECT_EQ(split_values[k], values[k]) << k;
}

TEST(Adam, RejectsInvalidOptions) {
  AdamOptions bad;
  bad.beta1 = 1.0;
  EXPECT_THROW(Adam<double>({}, bad), std::invalid_argument);
  bad = AdamOptions{};
  bad.learning_rate = -1.0;
  EXPECT_THROW(Adam<double>({}, bad), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp::nn
