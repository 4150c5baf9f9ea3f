// Tests of nn/conv2d.hpp: forward against a naive direct loop, backward against finite
// differences for several stride / padding / kernel combinations, initialisation, and the
// autoencoder's layer sizes (paper, Section "Learning the Context").
#include "nn/conv2d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "conv_test_util.hpp"
#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

struct ConvCase {
  Index kernel, stride, padding, height, width;
};

std::string describe(const ConvCase& c) {
  return "k" + std::to_string(c.kernel) + "s" + std::to_string(c.stride) + "p" +
         std::to_string(c.padding) + "_" + std::to_string(c.height) + "x" + std::to_string(c.width);
}

std::string case_name(const ::testing::TestParamInfo<ConvCase>& info) {
  return describe(info.param);
}

void PrintTo(const ConvCase& c, std::ostream* os) { *os << describe(c); }

const ConvCase kCases[] = {
    {3, 1, 0, 6, 5}, {3, 1, 1, 5, 6}, {3, 2, 1, 7, 6}, {3, 2, 0, 7, 7}, {2, 2, 0, 6, 4},
    {1, 1, 0, 3, 4}, {3, 3, 2, 5, 5}, {5, 2, 2, 6, 7}, {3, 2, 1, 8, 6}, {3, 1, 1, 1, 1},
};

class Conv2dCases : public ::testing::TestWithParam<ConvCase> {
 protected:
  Conv2dOptions options() const {
    const ConvCase& c = GetParam();
    return {2, 3, c.kernel, c.stride, c.padding};
  }
};

using Conv2dGrad = Conv2dCases;
using Conv2dForward = Conv2dCases;
using Conv2dFusedRelu = Conv2dCases;

TEST_P(Conv2dForward, MatchesNaiveDirectLoop) {
  const ConvCase& c = GetParam();
  Rng rng(20);
  Conv2d<double> conv(options(), c.height, c.width, rng);
  const MatD x = testing::random_matrix(3, conv.input_shape().size(), rng);
  MatD y(3, conv.output_shape().size());
  conv.forward(x, y);
  const MatD expected = testing::naive_conv2d(x, conv.input_shape(), conv.weight(), conv.bias(),
                                              c.kernel, c.stride, c.padding);
  ASSERT_EQ(expected.cols(), y.cols());
  EXPECT_LE((y - expected).norm(), 1e-12 * expected.norm());
}

TEST_P(Conv2dGrad, MatchesFiniteDifferences) {
  const ConvCase& c = GetParam();
  Rng rng(21);
  Conv2d<double> conv(options(), c.height, c.width, rng);
  const Index n = 2;
  MatD x = testing::random_matrix(n, conv.input_shape().size(), rng);
  const MatD r = testing::random_matrix(n, conv.output_shape().size(), rng);
  auto params = conv.parameters();
  zero_grad(params);
  MatD dx(n, conv.input_shape().size());
  conv.backward(x, r, dx);
  auto loss = [&] {
    MatD y(n, conv.output_shape().size());
    conv.forward(x, y);
    return testing::weighted_sum(y, r);
  };
  testing::expect_gradients_match(loss, testing::cases_for("x", x, dx, params));
}

// forward(relu) is relu(forward) and backward(relu_input) masks the input gradient by x > 0,
// with the same parameter gradients (nn/relu_fusion.hpp).
TEST_P(Conv2dFusedRelu, EqualsSeparateRelu) {
  const ConvCase& c = GetParam();
  Rng rng(28);
  Conv2d<double> conv(options(), c.height, c.width, rng);
  const Index n = 3;
  const MatD x = testing::random_matrix(n, conv.input_shape().size(), rng).cwiseMax(0.0);
  MatD y(n, conv.output_shape().size()), y_relu(n, conv.output_shape().size());
  conv.forward(x, y);
  conv.forward(x, y_relu, /*relu=*/true);
  EXPECT_EQ(y_relu, y.cwiseMax(0.0));
  const MatD dy = testing::random_matrix(n, conv.output_shape().size(), rng);
  auto params = conv.parameters();
  MatD dx(n, x.cols()), dx_masked(n, x.cols());
  zero_grad(params);
  conv.backward(x, dy, dx);
  const MatD weight_grad = conv.weight_grad();
  zero_grad(params);
  conv.backward(x, dy, dx_masked, /*relu_input=*/true);
  EXPECT_EQ(dx_masked, (x.array() > 0.0).select(dx, 0.0));
  EXPECT_EQ(conv.weight_grad(), weight_grad);
}

INSTANTIATE_TEST_SUITE_P(StridePadding, Conv2dForward, ::testing::ValuesIn(kCases), case_name);
INSTANTIATE_TEST_SUITE_P(StridePadding, Conv2dFusedRelu, ::testing::ValuesIn(kCases), case_name);
INSTANTIATE_TEST_SUITE_P(StridePadding, Conv2dGrad, ::testing::ValuesIn(kCases), case_name);

// Kernel 3, stride 2, padding 1 with 16 channels or more on both sides runs the stride-2
// Winograd algorithm (nn/winograd_stride2_conv3x3.hpp): the layer's results and gradients must be
// the same functions as on the im2col path.
TEST(Conv2d, ChoosesItsAlgorithmByKernelStrideAndChannels) {
  Rng rng(26);
  EXPECT_EQ(Conv2d<float>({3, 32, 3, 2, 1}, 8, 8, rng).algorithm(), ConvAlgorithm::kIm2col);
  EXPECT_EQ(Conv2d<float>({15, 32, 3, 2, 1}, 8, 8, rng).algorithm(), ConvAlgorithm::kIm2col);
  EXPECT_EQ(Conv2d<float>({16, 16, 3, 2, 1}, 8, 8, rng).algorithm(),
            ConvAlgorithm::kWinogradStride2);
  EXPECT_EQ(Conv2d<float>({16, 16, 3, 2, 0}, 8, 8, rng).algorithm(), ConvAlgorithm::kIm2col);
  EXPECT_EQ(Conv2d<float>({3, 4, 3, 1, 1}, 8, 8, rng).algorithm(), ConvAlgorithm::kWinograd);
}

TEST(Conv2d, StrideTwoWinogradPathMatchesNaiveLoopAndFiniteDifferences) {
  Rng rng(27);
  for (const Index height : {7, 8}) {
    Conv2d<double> conv({16, 16, 3, 2, 1}, height, 6, rng);
    ASSERT_EQ(conv.algorithm(), ConvAlgorithm::kWinogradStride2);
    const Index n = 2;
    MatD x = testing::random_matrix(n, conv.input_shape().size(), rng);
    const MatD r = testing::random_matrix(n, conv.output_shape().size(), rng);
    MatD y(n, conv.output_shape().size());
    conv.forward(x, y);
    const MatD expected =
        testing::naive_conv2d(x, conv.input_shape(), conv.weight(), conv.bias(), 3, 2, 1);
    EXPECT_LE((y - expected).norm(), 1e-12 * expected.norm()) << height;
    auto params = conv.parameters();
    zero_grad(params);
    MatD dx(n, conv.input_shape().size());
    conv.backward(x, r, dx);
    auto loss = [&] {
      MatD out(n, conv.output_shape().size());
      conv.forward(x, out);
      return testing::weighted_sum(out, r);
    };
    testing::expect_gradients_match(loss, testing::cases_for("x", x, dx, params));
  }
}

TEST(Conv2dGrad, ParamOnlyBackwardMatchesFullBackward) {
  Rng rng(22);
  Conv2d<double> conv({2, 4, 3, 2, 1}, 8, 8, rng);
  const MatD x = testing::random_matrix(3, conv.input_shape().size(), rng);
  const MatD dy = testing::random_matrix(3, conv.output_shape().size(), rng);
  auto params = conv.parameters();
  zero_grad(params);
  MatD dx(3, conv.input_shape().size());
  conv.backward(x, dy, dx);
  const MatD full = conv.weight_grad();
  zero_grad(params);
  conv.accumulate_param_grad(x, dy);
  EXPECT_TRUE(conv.weight_grad().isApprox(full, 1e-14));
}

TEST(Conv2d, FloatForwardAgreesWithDouble) {
  Rng a(23), b(23);
  Conv2d<double> cd({3, 8, 3, 2, 1}, 16, 16, a);
  Conv2d<float> cf({3, 8, 3, 2, 1}, 16, 16, b);
  Rng data(24);
  const MatD x = testing::random_matrix(2, cd.input_shape().size(), data);
  MatD yd(2, cd.output_shape().size());
  Mat<float> yf(2, cf.output_shape().size());
  cd.forward(x, yd);
  const Mat<float> xf = x.cast<float>();
  cf.forward(xf, yf);
  EXPECT_LE((yf.cast<double>() - yd).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(Conv2d, AutoencoderEncoderShapes) {
  // Paper: kernel 3, strides [2, 1, 2, 1, 2], filters [32, 32, 64, 64, 64] on 64x64 images
  // (padding 1 keeps stride-1 layers size-preserving).
  Rng rng(25);
  const Index strides[] = {2, 1, 2, 1, 2};
  const Index filters[] = {32, 32, 64, 64, 64};
  const Index expected_size[] = {32, 32, 16, 16, 8};
  ImageShape shape{3, 64, 64};
  for (int l = 0; l < 5; ++l) {
    Conv2d<float> conv({shape.channels, filters[l], 3, strides[l], 1}, shape.height, shape.width,
                       rng);
    shape = conv.output_shape();
    EXPECT_EQ(shape, (ImageShape{filters[l], expected_size[l], expected_size[l]}));
  }
}

TEST(Conv2dInit, WithinPyTorchBoundAndDeterministic) {
  Rng a(26), b(26);
  Conv2d<float> ca({4, 6, 3, 1, 1}, 5, 5, a), cb({4, 6, 3, 1, 1}, 5, 5, b);
  const float bound = 1.0f / std::sqrt(4.0f * 9.0f);
  EXPECT_LE(ca.weight().cwiseAbs().maxCoeff(), bound);
  EXPECT_GT(ca.weight().cwiseAbs().maxCoeff(), 0.8f * bound);
  EXPECT_LE(ca.bias().cwiseAbs().maxCoeff(), bound);
  EXPECT_EQ(ca.weight(), cb.weight());
  EXPECT_EQ(ca.bias(), cb.bias());
  const auto params = ca.parameters("enc.0.");
  EXPECT_EQ(params[0].name, "enc.0.weight");
  EXPECT_EQ(params[0].shape, (std::vector<std::int64_t>{6, 4, 3, 3}));
}

TEST(Conv2d, RejectsInvalidGeometryAndShapes) {
  Rng rng(27);
  EXPECT_THROW(Conv2d<double>({1, 1, 5, 1, 0}, 3, 3, rng), std::invalid_argument);
  EXPECT_THROW(Conv2d<double>({1, 1, 3, 0, 0}, 3, 3, rng), std::invalid_argument);
  Conv2d<double> conv({1, 2, 3, 1, 1}, 4, 4, rng);
  MatD x(1, 15), y(1, 32);
  EXPECT_THROW(conv.forward(x, y), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp::nn
