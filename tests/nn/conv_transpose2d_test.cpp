// Tests of nn/conv_transpose2d.hpp: forward against a naive scatter loop, backward against
// finite differences (including stride 2 with output_padding, as in the autoencoder decoder),
// and the adjoint identity <C x, y> = <x, C^T y> with Conv2d.
#include "nn/conv_transpose2d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "conv_test_util.hpp"
#include "gradient_check.hpp"
#include "nn/conv2d.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

struct TransposeCase {
  Index kernel, stride, padding, output_padding, height, width;
};

std::string describe(const TransposeCase& c) {
  return "k" + std::to_string(c.kernel) + "s" + std::to_string(c.stride) + "p" +
         std::to_string(c.padding) + "op" + std::to_string(c.output_padding) + "_" +
         std::to_string(c.height) + "x" + std::to_string(c.width);
}

std::string transpose_case_name(const ::testing::TestParamInfo<TransposeCase>& info) {
  return describe(info.param);
}

void PrintTo(const TransposeCase& c, std::ostream* os) { *os << describe(c); }

constexpr TransposeCase kTransposeCases[] = {
    {3, 2, 1, 1, 4, 3}, {3, 2, 1, 0, 3, 4}, {3, 1, 1, 0, 4, 4}, {3, 1, 0, 0, 3, 2},
    {2, 2, 0, 0, 3, 3}, {3, 3, 1, 2, 2, 3}, {4, 2, 1, 1, 3, 3},
};

class ConvTranspose2dCases : public ::testing::TestWithParam<TransposeCase> {
 protected:
  ConvTranspose2dOptions options() const {
    const TransposeCase& c = GetParam();
    return {3, 2, c.kernel, c.stride, c.padding, c.output_padding};
  }
};

using ConvTranspose2dGrad = ConvTranspose2dCases;
using ConvTranspose2dForward = ConvTranspose2dCases;
using ConvTranspose2dAdjoint = ConvTranspose2dCases;
using ConvTranspose2dFusedRelu = ConvTranspose2dCases;

TEST_P(ConvTranspose2dForward, MatchesNaiveScatterLoop) {
  const TransposeCase& c = GetParam();
  Rng rng(30);
  ConvTranspose2d<double> layer(options(), c.height, c.width, rng);
  const MatD x = testing::random_matrix(2, layer.input_shape().size(), rng);
  MatD y(2, layer.output_shape().size());
  layer.forward(x, y);
  const MatD expected =
      testing::naive_conv_transpose2d(x, layer.input_shape(), layer.weight(), layer.bias(),
                                      c.kernel, c.stride, c.padding, c.output_padding);
  ASSERT_EQ(expected.cols(), y.cols());
  EXPECT_LE((y - expected).norm(), 1e-12 * expected.norm());
}

TEST_P(ConvTranspose2dGrad, MatchesFiniteDifferences) {
  const TransposeCase& c = GetParam();
  Rng rng(31);
  ConvTranspose2d<double> layer(options(), c.height, c.width, rng);
  const Index n = 2;
  MatD x = testing::random_matrix(n, layer.input_shape().size(), rng);
  const MatD r = testing::random_matrix(n, layer.output_shape().size(), rng);
  auto params = layer.parameters();
  zero_grad(params);
  MatD dx(n, layer.input_shape().size());
  layer.backward(x, r, dx);
  auto loss = [&] {
    MatD y(n, layer.output_shape().size());
    layer.forward(x, y);
    return testing::weighted_sum(y, r);
  };
  testing::expect_gradients_match(loss, testing::cases_for("x", x, dx, params));
}

TEST_P(ConvTranspose2dAdjoint, IsAdjointOfConv2dWithSharedWeights) {
  const TransposeCase& c = GetParam();
  Rng rng(32);
  ConvTranspose2d<double> transpose(options(), c.height, c.width, rng);
  const ImageShape big = transpose.output_shape();  // Conv2d input, ConvTranspose2d output
  Conv2d<double> conv(
      {big.channels, transpose.input_shape().channels, c.kernel, c.stride, c.padding}, big.height,
      big.width, rng);
  ASSERT_EQ(conv.output_shape(), transpose.input_shape());
  // Conv2d weight (Cout, Cin, k, k) and ConvTranspose2d weight (Cin', Cout', k, k) with
  // Cin' = Cout, Cout' = Cin share one memory layout.
  conv.weight() = transpose.weight();
  conv.bias().setZero();
  transpose.bias().setZero();
  const MatD x = testing::random_matrix(2, big.size(), rng);
  const MatD y = testing::random_matrix(2, conv.output_shape().size(), rng);
  MatD cx(2, conv.output_shape().size()), cty(2, big.size());
  conv.forward(x, cx);
  transpose.forward(y, cty);
  const double lhs = (cx.array() * y.array()).sum();
  const double rhs = (x.array() * cty.array()).sum();
  EXPECT_GT(std::abs(lhs), 1e-3);
  EXPECT_NEAR(lhs, rhs, 1e-12 * (std::abs(lhs) + 1.0));
}

// forward(relu) is relu(forward) and backward(relu_input) masks the input gradient by x > 0,
// with the same parameter gradients (nn/relu_fusion.hpp).
TEST_P(ConvTranspose2dFusedRelu, EqualsSeparateRelu) {
  const TransposeCase& c = GetParam();
  Rng rng(33);
  ConvTranspose2d<double> layer(options(), c.height, c.width, rng);
  const Index n = 3;
  const MatD x = testing::random_matrix(n, layer.input_shape().size(), rng).cwiseMax(0.0);
  MatD y(n, layer.output_shape().size()), y_relu(n, layer.output_shape().size());
  layer.forward(x, y);
  layer.forward(x, y_relu, /*relu=*/true);
  EXPECT_EQ(y_relu, y.cwiseMax(0.0));
  const MatD dy = testing::random_matrix(n, layer.output_shape().size(), rng);
  auto params = layer.parameters();
  MatD dx(n, x.cols()), dx_masked(n, x.cols());
  zero_grad(params);
  layer.backward(x, dy, dx);
  const MatD weight_grad = layer.weight_grad();
  zero_grad(params);
  layer.backward(x, dy, dx_masked, /*relu_input=*/true);
  EXPECT_EQ(dx_masked, (x.array() > 0.0).select(dx, 0.0));
  EXPECT_EQ(layer.weight_grad(), weight_grad);
}

INSTANTIATE_TEST_SUITE_P(StridePadding, ConvTranspose2dFusedRelu,
                         ::testing::ValuesIn(kTransposeCases), transpose_case_name);
INSTANTIATE_TEST_SUITE_P(StridePadding, ConvTranspose2dForward,
                         ::testing::ValuesIn(kTransposeCases), transpose_case_name);
INSTANTIATE_TEST_SUITE_P(StridePadding, ConvTranspose2dGrad, ::testing::ValuesIn(kTransposeCases),
                         transpose_case_name);
INSTANTIATE_TEST_SUITE_P(StridePadding, ConvTranspose2dAdjoint,
                         ::testing::ValuesIn(kTransposeCases), transpose_case_name);

// Kernel 3, stride 2, padding 1 with 16 channels or more on both sides runs the adjoint of the
// stride-2 Winograd convolution (nn/winograd_stride2_conv3x3.hpp), with either output padding.
TEST(ConvTranspose2d, ChoosesItsAlgorithmByKernelStrideAndChannels) {
  Rng rng(36);
  EXPECT_EQ(ConvTranspose2d<float>({32, 3, 3, 2, 1, 1}, 8, 8, rng).algorithm(),
            ConvAlgorithm::kIm2col);
  EXPECT_EQ(ConvTranspose2d<float>({16, 16, 3, 2, 1, 1}, 8, 8, rng).algorithm(),
            ConvAlgorithm::kWinogradStride2);
  EXPECT_EQ(ConvTranspose2d<float>({4, 3, 3, 1, 1, 0}, 8, 8, rng).algorithm(),
            ConvAlgorithm::kWinograd);
}

TEST(ConvTranspose2d, StrideTwoWinogradPathMatchesNaiveLoopAndFiniteDifferences) {
  Rng rng(37);
  for (const Index output_padding : {0, 1}) {
    ConvTranspose2d<double> layer({16, 16, 3, 2, 1, output_padding}, 4, 3, rng);
    ASSERT_EQ(layer.algorithm(), ConvAlgorithm::kWinogradStride2);
    const Index n = 2;
    MatD x = testing::random_matrix(n, layer.input_shape().size(), rng);
    const MatD r = testing::random_matrix(n, layer.output_shape().size(), rng);
    MatD y(n, layer.output_shape().size());
    layer.forward(x, y);
    const MatD expected = testing::naive_conv_transpose2d(x, layer.input_shape(), layer.weight(),
                                                          layer.bias(), 3, 2, 1, output_padding);
    EXPECT_LE((y - expected).norm(), 1e-12 * expected.norm()) << output_padding;
    auto params = layer.parameters();
    zero_grad(params);
    MatD dx(n, layer.input_shape().size());
    layer.backward(x, r, dx);
    auto loss = [&] {
      MatD out(n, layer.output_shape().size());
      layer.forward(x, out);
      return testing::weighted_sum(out, r);
    };
    testing::expect_gradients_match(loss, testing::cases_for("x", x, dx, params));
  }
}

TEST(ConvTranspose2d, AutoencoderDecoderShapesMirrorEncoder) {
  // The decoder undoes strides [2, 1, 2, 1, 2] back to 64x64 (output_padding 1 for stride 2).
  Rng rng(33);
  const Index strides[] = {2, 1, 2, 1, 2};
  const Index channels[] = {64, 64, 32, 32, 3};
  const Index expected_size[] = {16, 16, 32, 32, 64};
  ImageShape shape{64, 8, 8};
  for (int l = 0; l < 5; ++l) {
    ConvTranspose2d<float> layer(
        {shape.channels, channels[l], 3, strides[l], 1, strides[l] == 2 ? 1 : 0}, shape.height,
        shape.width, rng);
    shape = layer.output_shape();
    EXPECT_EQ(shape, (ImageShape{channels[l], expected_size[l], expected_size[l]}));
  }
}

TEST(ConvTranspose2dInit, UsesPyTorchFanInOfOutputChannels) {
  // torch computes fan_in from weight dimension 1, which is Cout for a transposed convolution.
  Rng rng(34);
  ConvTranspose2d<float> layer({2, 16, 3, 2, 1, 1}, 4, 4, rng);
  const float bound = 1.0f / std::sqrt(16.0f * 9.0f);
  EXPECT_LE(layer.weight().cwiseAbs().maxCoeff(), bound);
  EXPECT_GT(layer.weight().cwiseAbs().maxCoeff(), 0.8f * bound);
  EXPECT_LE(layer.bias().cwiseAbs().maxCoeff(), bound);
  const auto params = layer.parameters();
  EXPECT_EQ(params[0].shape, (std::vector<std::int64_t>{2, 16, 3, 3}));
  EXPECT_EQ(params[1].shape, (std::vector<std::int64_t>{16}));
}

TEST(ConvTranspose2d, RejectsOutputPaddingNotBelowStride) {
  Rng rng(35);
  EXPECT_THROW(ConvTranspose2d<double>({1, 1, 3, 2, 1, 2}, 4, 4, rng), std::invalid_argument);
  EXPECT_THROW(ConvTranspose2d<double>({1, 1, 3, 1, 0, 1}, 4, 4, rng), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp::nn
