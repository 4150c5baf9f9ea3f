// Tests of nn/mlp.hpp: gradients of inputs and all parameters against finite differences,
// equivalence with a hand-composed Linear/ReLU stack, parameter names and counts for the
// paper's CNMP sizes, and buffer reuse across batch sizes.
#include "nn/mlp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "gradient_check.hpp"
#include "nn/activation.hpp"
#include "nn/gemm.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

// Input and parameter gradients of a batch of `rows` against finite differences.
void expect_mlp_gradients_match(Mlp<double>& mlp, int rows, int d_in, int d_out, Rng& rng) {
  MatD x = testing::random_matrix(rows, d_in, rng);
  const MatD r = testing::random_matrix(rows, d_out, rng);
  auto params = mlp.parameters();
  zero_grad(params);
  mlp.forward(x);
  const MatD dx = mlp.backward(r);
  auto loss = [&] { return testing::weighted_sum(mlp.forward(x), r); };
  testing::expect_gradients_match(loss, testing::cases_for("x", x, dx, params));
}

TEST(MlpGrad, MatchesFiniteDifferences) {
  Rng rng(50);
  Mlp<double> mlp({3, 6, 5, 2}, rng);
  // Run a larger batch first so the check also covers reused, larger-than-needed buffers.
  mlp.forward(testing::random_matrix(9, 3, rng));
  expect_mlp_gradients_match(mlp, 4, 3, 2, rng);
}

TEST(MlpGrad, SingleLayerMatchesFiniteDifferences) {
  Rng rng(51);
  Mlp<double> mlp({4, 3}, rng);
  expect_mlp_gradients_match(mlp, 2, 4, 3, rng);
}

TEST(MlpGrad, ParamsOnlyBackwardGivesSameParameterGradients) {
  Rng rng(52);
  Mlp<double> mlp({3, 8, 8, 2}, rng);
  const MatD x = testing::random_matrix(5, 3, rng);
  const MatD r = testing::random_matrix(5, 2, rng);
  auto params = mlp.parameters();
  zero_grad(params);
  mlp.forward(x);
  mlp.backward(r);
  std::vector<Eigen::VectorXd> full;
  for (const auto& p : params) full.push_back(p.grads());
  zero_grad(params);
  mlp.forward(x);
  mlp.backward_params_only(r);
  for (std::size_t k = 0; k < params.size(); ++k)
    EXPECT_TRUE(params[k].grads().isApprox(full[k], 1e-14)) << params[k].name;
}

TEST(Mlp, ForwardEqualsLinearReluComposition) {
  Rng a(53), b(53);
  Mlp<double> mlp({4, 7, 3}, a);
  Linear<double> first(4, 7, b), second(7, 3, b);
  const MatD x = testing::random_matrix(3, 4, a);
  MatD h(3, 7), y(3, 3);
  first.forward(x, h);
  Relu<double>().forward(h, h);
  second.forward(h, y);
  EXPECT_TRUE(MatD(mlp.forward(x)).isApprox(y, 1e-14));
}

TEST(Mlp, CnmpSizedParameterCountAndNames) {
  // Paper: encoder 3 layers, decoder 4 layers, width 128.
  Rng rng(54);
  Mlp<float> encoder({4, 128, 128, 128}, rng);
  EXPECT_EQ(encoder.num_layers(), 3);
  EXPECT_EQ(encoder.num_parameters(), (4 * 128 + 128) + 2 * (128 * 128 + 128));
  const auto params = encoder.parameters("encoder.");
  ASSERT_EQ(params.size(), 6u);
  EXPECT_EQ(params[0].name, "encoder.layers.0.weight");
  EXPECT_EQ(params[0].shape, (std::vector<std::int64_t>{128, 4}));
  EXPECT_EQ(params[5].name, "encoder.layers.2.bias");
  EXPECT_EQ(count_parameters(params), encoder.num_parameters());
}

TEST(Mlp, SameSeedGivesIdenticalWeights) {
  Rng a(55), b(55);
  Mlp<float> ma({3, 16, 2}, a), mb({3, 16, 2}, b);
  for (Index i = 0; i < ma.num_layers(); ++i) {
    EXPECT_EQ(ma.layer(i).weight(), mb.layer(i).weight());
    EXPECT_EQ(ma.layer(i).bias(), mb.layer(i).bias());
  }
}

TEST(Mlp, RejectsBadSizesAndShapes) {
  Rng rng(56);
  EXPECT_THROW(Mlp<double>({3}, rng), std::invalid_argument);
  Mlp<double> mlp({3, 4, 2}, rng);
  EXPECT_THROW(mlp.forward(MatD(2, 4)), std::invalid_argument);
  mlp.forward(MatD::Zero(2, 3));
  EXPECT_THROW(mlp.backward(MatD(3, 2)), std::invalid_argument);
}

// forward_part and backward_part run by a team of threads give the bits of forward and backward
// (nn/team.hpp): widths that do not split evenly, and a team larger than a narrow layer.
TEST(MlpTeam, PartsOnThreadsGiveExactlyTheWholePasses) {
  if (!gemm_float_split_exact()) GTEST_SKIP() << "float products run on Eigen in this build";
  for (int members : {2, 3}) {
    Rng rng(57);
    Mlp<float> whole({5, 37, 223, 3}, rng);
    Mlp<float> split = whole;
    Mat<float> x(11, 5), dy(11, 3);
    for (Index i = 0; i < x.size(); ++i) x.data()[i] = std::sin(0.7f * static_cast<float>(i));
    for (Index i = 0; i < dy.size(); ++i) dy.data()[i] = std::cos(0.3f * static_cast<float>(i));
    const Mat<float> y = whole.forward(x);
    const Mat<float> dx = whole.backward(dy);

    split.prepare(x.rows());
    split.input() = x;
    SpinBarrier barrier(members);
    Mat<float> split_dx;
    std::vector<std::thread> threads;
    const auto member = [&](int index) {
      const Team team{index, members, &barrier};
      split.forward_part(team);
      const auto grad = split.backward_part(dy, true, team);
      if (index == 0) split_dx = grad;
    };
    for (int m = 1; m < members; ++m) threads.emplace_back(member, m);
    member(0);
    for (auto& t : threads) t.join();

    EXPECT_EQ(0, std::memcmp(y.data(), split.output().data(), sizeof(float) * y.size()));
    ASSERT_EQ(split_dx.rows(), dx.rows());
    EXPECT_EQ(0, std::memcmp(dx.data(), split_dx.data(), sizeof(float) * dx.size()));
    const auto a = whole.parameters(), b = split.parameters();
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(0, std::memcmp(a[k].grad, b[k].grad, sizeof(float) * a[k].size()))
          << members << " members, " << a[k].name;
    }
  }
}

}  // namespace
}  // namespace corrmp::nn
