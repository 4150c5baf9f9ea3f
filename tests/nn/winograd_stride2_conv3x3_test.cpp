// Tests of nn/winograd_stride2_conv3x3.hpp against direct loops: the convolution and the
// transposed convolution, forward and backward (weight, bias and input gradients), on odd, even
// and tiny image sizes, batches cut into several chunks, the fused ReLUs, and float against double.
#include "nn/winograd_stride2_conv3x3.hpp"

#include <gtest/gtest.h>

#include "conv_test_util.hpp"
#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

struct Stride2Shape {
  Index full_channels, half_channels, height, width, batch;
  Index half_height() const { return (height + 1) / 2; }
  Index half_width() const { return (width + 1) / 2; }
  Index full_size() const { return full_channels * height * width; }
  Index half_size() const { return half_channels * half_height() * half_width(); }
};

const Stride2Shape kStride2Shapes[] = {
    {3, 4, 10, 12, 2}, {2, 3, 7, 9, 2},  {2, 2, 1, 1, 3},     {2, 3, 2, 3, 2},
    {3, 2, 17, 1, 2},  {4, 5, 9, 16, 1}, {64, 16, 32, 32, 5},  // chunks of 2, 2 and 1 images
};

// dL/dW (half x full x 3 x 3) and dL/dfull of half = conv(full) for dL/dhalf = dy, by direct loops.
struct Stride2Grads {
  MatD weight, full;
};
Stride2Grads direct_backward(const Stride2Shape& s, const MatD& full, const MatD& dy,
                             const MatD& w) {
  Stride2Grads g{MatD::Zero(s.half_channels, s.full_channels * 9),
                 MatD::Zero(full.rows(), full.cols())};
  const Index H = s.height, W = s.width, h2 = s.half_height(), w2 = s.half_width();
  for (Index n = 0; n < full.rows(); ++n)
    for (Index o = 0; o < s.half_channels; ++o)
      for (Index h = 0; h < h2; ++h)
        for (Index v = 0; v < w2; ++v) {
          const double d = dy(n, (o * h2 + h) * w2 + v);
          for (Index c = 0; c < s.full_channels; ++c)
            for (Index i = 0; i < 3; ++i)
              for (Index j = 0; j < 3; ++j) {
                const Index hh = 2 * h - 1 + i, vv = 2 * v - 1 + j;
                if (hh < 0 || hh >= H || vv < 0 || vv >= W) continue;
                const Index xi = (c * H + hh) * W + vv;
                g.weight(o, c * 9 + i * 3 + j) += d * full(n, xi);
                g.full(n, xi) += d * w(o, c * 9 + i * 3 + j);
              }
        }
  return g;
}

Vec<double> channel_sums(const MatD& images, Index channels) {
  const Index pixels = images.cols() / channels;
  Vec<double> sums = Vec<double>::Zero(channels);
  for (Index n = 0; n < images.rows(); ++n)
    for (Index c = 0; c < channels; ++c) sums[c] += images.row(n).segment(c * pixels, pixels).sum();
  return sums;
}

double relative_error(const MatD& got, const MatD& expected) {
  return (got - expected).norm() / std::max(expected.norm(), 1e-300);
}

TEST(WinogradStride2Conv3x3, ConvolutionMatchesDirectLoops) {
  Rng rng(70);
  for (const Stride2Shape& s : kStride2Shapes) {
    WinogradStride2Conv3x3<double> conv(s.full_channels, s.half_channels, s.height, s.width);
    const MatD w = testing::random_matrix(s.half_channels, s.full_channels * 9, rng);
    const Vec<double> b = testing::random_matrix(s.half_channels, 1, rng);
    const MatD x = testing::random_matrix(s.batch, s.full_size(), rng);
    MatD y(s.batch, s.half_size());
    conv.convolve(w.data(), b.data(), x, y, /*relu=*/false);
    const MatD expected =
        testing::naive_conv2d(x, {s.full_channels, s.height, s.width}, w, b, 3, 2, 1);
    EXPECT_LE(relative_error(y, expected), 1e-12) << s.height << "x" << s.width;

    const MatD dy = testing::random_matrix(s.batch, s.half_size(), rng);
    MatD dw = MatD::Constant(s.half_channels, s.full_channels * 9, 0.5), dx(s.batch, s.full_size());
    Vec<double> db = Vec<double>::Constant(s.half_channels, 0.5);  // gradients accumulate
    conv.convolve_backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols(), false);
    const Stride2Grads g = direct_backward(s, x, dy, w);
    EXPECT_LE(relative_error((dw.array() - 0.5).matrix(), g.weight), 1e-12) << s.height;
    EXPECT_LE(relative_error((db.array() - 0.5).matrix(), channel_sums(dy, s.half_channels)),
              1e-12);
    EXPECT_LE(relative_error(dx, g.full), 1e-12) << s.height << "x" << s.width;
  }
}

// The transposed convolution (output padding 1 for an even full side, 0 for an odd one) is the
// adjoint of the convolution with the same weights.
TEST(WinogradStride2Conv3x3, TransposeMatchesDirectLoops) {
  Rng rng(71);
  for (const Stride2Shape& s : kStride2Shapes) {
    WinogradStride2Conv3x3<double> conv(s.full_channels, s.half_channels, s.height, s.width);
    const Index output_padding = s.height - (2 * s.half_height() - 1);
    if (s.width - (2 * s.half_width() - 1) != output_padding) continue;  // one padding for both
    const MatD w = testing::random_matrix(s.half_channels, s.full_channels * 9, rng);
    const Vec<double> b = testing::random_matrix(s.full_channels, 1, rng);
    const MatD x = testing::random_matrix(s.batch, s.half_size(), rng);
    MatD y(s.batch, s.full_size());
    conv.convolve_transposed(w.data(), b.data(), x, y, /*relu=*/false);
    const MatD expected = testing::naive_conv_transpose2d(
        x, {s.half_channels, s.half_height(), s.half_width()}, w, b, 3, 2, 1, output_padding);
    EXPECT_LE(relative_error(y, expected), 1e-12) << s.height << "x" << s.width;

    const MatD dy = testing::random_matrix(s.batch, s.full_size(), rng);
    MatD dw = MatD::Constant(s.half_channels, s.full_channels * 9, 0.5), dx(s.batch, s.half_size());
    Vec<double> db = Vec<double>::Constant(s.full_channels, 0.5);
    conv.convolve_transposed_backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols(),
                                      false);
    // The weight gradient of the adjoint is the convolution's with the roles of x and dy swapped.
    const Stride2Grads g = direct_backward(s, dy, x, w);
    EXPECT_LE(relative_error((dw.array() - 0.5).matrix(), g.weight), 1e-12) << s.height;
    EXPECT_LE(relative_error((db.array() - 0.5).matrix(), channel_sums(dy, s.full_channels)),
              1e-12);
    const MatD expected_dx = testing::naive_conv2d(dy, {s.full_channels, s.height, s.width}, w,
                                                   Vec<double>::Zero(s.half_channels), 3, 2, 1);
    EXPECT_LE(relative_error(dx, expected_dx), 1e-12) << s.height << "x" << s.width;
  }
}

TEST(WinogradStride2Conv3x3, FusedRelus) {
  Rng rng(72);
  const Stride2Shape s{3, 4, 10, 9, 2};
  WinogradStride2Conv3x3<double> conv(s.full_channels, s.half_channels, s.height, s.width);
  const MatD w = testing::random_matrix(s.half_channels, s.full_channels * 9, rng);
  const Vec<double> b_half = testing::random_matrix(s.half_channels, 1, rng);
  const Vec<double> b_full = testing::random_matrix(s.full_channels, 1, rng);
  const MatD full = testing::random_matrix(s.batch, s.full_size(), rng).cwiseMax(0.0);
  const MatD half = testing::random_matrix(s.batch, s.half_size(), rng).cwiseMax(0.0);
  MatD y(s.batch, s.half_size()), y_relu(s.batch, s.half_size());
  conv.convolve(w.data(), b_half.data(), full, y, false);
  conv.convolve(w.data(), b_half.data(), full, y_relu, true);
  EXPECT_EQ(y_relu, y.cwiseMax(0.0));
  MatD z(s.batch, s.full_size()), z_relu(s.batch, s.full_size());
  conv.convolve_transposed(w.data(), b_full.data(), half, z, false);
  conv.convolve_transposed(w.data(), b_full.data(), half, z_relu, true);
  EXPECT_EQ(z_relu, z.cwiseMax(0.0));

  MatD dw = MatD::Zero(s.half_channels, s.full_channels * 9);
  Vec<double> db_half = Vec<double>::Zero(s.half_channels),
              db_full = Vec<double>::Zero(s.full_channels);
  const MatD dy_half = testing::random_matrix(s.batch, s.half_size(), rng);
  MatD dx(s.batch, s.full_size()), dx_masked(s.batch, s.full_size());
  conv.convolve_backward(w.data(), full, dy_half, dw.data(), db_half.data(), dx.data(), dx.cols(),
                         false);
  conv.convolve_backward(w.data(), full, dy_half, dw.data(), db_half.data(), dx_masked.data(),
                         dx.cols(), true);
  EXPECT_EQ(dx_masked, (full.array() > 0.0).select(dx, 0.0));
  const MatD dy_full = testing::random_matrix(s.batch, s.full_size(), rng);
  MatD dh(s.batch, s.half_size()), dh_masked(s.batch, s.half_size());
  conv.convolve_transposed_backward(w.data(), half, dy_full, dw.data(), db_full.data(), dh.data(),
                                    dh.cols(), false);
  conv.convolve_transposed_backward(w.data(), half, dy_full, dw.data(), db_full.data(),
                                    dh_masked.data(), dh.cols(), true);
  EXPECT_EQ(dh_masked, (half.array() > 0.0).select(dh, 0.0));
}

// One layer used on batches of 3, 11 (two chunks) and 1 images, with its weights changed in place
// between a forward and the backward (as an optimiser does): every result is that of the direct
// loops with the weights of the moment; an empty batch changes nothing.
TEST(WinogradStride2Conv3x3, ReusedOnOtherBatchesAndChangedWeights) {
  Rng rng(74);
  const Stride2Shape s{3, 4, 13, 11, 0};
  WinogradStride2Conv3x3<double> conv(s.full_channels, s.half_channels, s.height, s.width);
  MatD w = testing::random_matrix(s.half_channels, s.full_channels * 9, rng);
  const Vec<double> b = testing::random_matrix(s.half_channels, 1, rng);
  for (const Index batch : {3, 11, 1}) {
    const MatD x = testing::random_matrix(batch, s.full_size(), rng);
    const MatD dy = testing::random_matrix(batch, s.half_size(), rng);
    MatD y(batch, s.half_size());
    conv.convolve(w.data(), b.data(), x, y, false);
    EXPECT_LE(relative_error(
                  y, testing::naive_conv2d(x, {s.full_channels, s.height, s.width}, w, b, 3, 2, 1)),
              1e-12)
        << batch;
    w(1, 4) += 0.25;  // after the forward, before the backward
    MatD dw = MatD::Zero(w.rows(), w.cols()), dx(batch, s.full_size());
    Vec<double> db = Vec<double>::Zero(s.half_channels);
    conv.convolve_backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols(), false);
    const Stride2Grads g = direct_backward(s, x, dy, w);
    EXPECT_LE(relative_error(dw, g.weight), 1e-12) << batch;
    EXPECT_LE(relative_error(dx, g.full), 1e-12) << batch;
  }
  MatD dw = MatD::Constant(w.rows(), w.cols(), 0.5), none(0, s.half_size());
  Vec<double> db = Vec<double>::Constant(s.half_channels, 0.5);
  conv.convolve_backward(w.data(), MatD(0, s.full_size()), none, dw.data(), db.data(), nullptr, 0,
                         false);
  conv.convolve_transposed_backward(w.data(), none, MatD(0, s.full_size()), dw.data(), db.data(),
                                    nullptr, 0, false);
  EXPECT_TRUE((dw.array() == 0.5).all());
  EXPECT_TRUE((db.array() == 0.5).all());
}

// The float path (AVX-512 transposes and products where the build has them) against double:
// the autoencoder's sizes, and channel counts and sizes off the 16-lane blocks in two chunks.
TEST(WinogradStride2Conv3x3, FloatAgreesWithDouble) {
  Rng rng(73);
  const Stride2Shape shapes[] = {{32, 64, 32, 32, 2}, {64, 64, 16, 16, 3}, {20, 17, 13, 11, 11}};
  const auto close = [](const auto& f, const auto& d) {
    return (f.template cast<double>() - d).cwiseAbs().maxCoeff() <= 1e-5 * d.cwiseAbs().maxCoeff();
  };
  for (const Stride2Shape& s : shapes) {
    WinogradStride2Conv3x3<double> cd(s.full_channels, s.half_channels, s.height, s.width);
    WinogradStride2Conv3x3<float> cf(s.full_channels, s.half_channels, s.height, s.width);
    const MatD w = testing::random_matrix(s.half_channels, s.full_channels * 9, rng, -0.06, 0.06);
    const Vec<double> b_half = testing::random_matrix(s.half_channels, 1, rng, -0.06, 0.06);
    const Vec<double> b_full = testing::random_matrix(s.full_channels, 1, rng, -0.06, 0.06);
    const MatD full = testing::random_matrix(s.batch, s.full_size(), rng, 0.0, 1.0);
    const MatD half = testing::random_matrix(s.batch, s.half_size(), rng, 0.0, 1.0);
    const Mat<float> wf = w.cast<float>(), full_f = full.cast<float>(), half_f = half.cast<float>();
    const Vec<float> b_half_f = b_half.cast<float>(), b_full_f = b_full.cast<float>();

    MatD yd(s.batch, s.half_size()), zd(s.batch, s.full_size());
    Mat<float> yf(s.batch, s.half_size()), zf(s.batch, s.full_size());
    cd.convolve(w.data(), b_half.data(), full, yd, true);
    cf.convolve(wf.data(), b_half_f.data(), full_f, yf, true);
    EXPECT_TRUE(close(yf, yd)) << s.height;
    cd.convolve_transposed(w.data(), b_full.data(), half, zd, true);
    cf.convolve_transposed(wf.data(), b_full_f.data(), half_f, zf, true);
    EXPECT_TRUE(close(zf, zd)) << s.height;

    MatD dwd = MatD::Zero(w.rows(), w.cols()), dfd(s.batch, s.full_size()),
         dhd(s.batch, s.half_size());
    Mat<float> dwf = Mat<float>::Zero(w.rows(), w.cols()), dff(s.batch, s.full_size()),
               dhf(s.batch, s.half_size());
    Vec<double> dbd = Vec<double>::Zero(s.half_channels);
    Vec<float> dbf = Vec<float>::Zero(s.half_channels);
    cd.convolve_backward(w.data(), full, half, dwd.data(), dbd.data(), dfd.data(), dfd.cols(),
                         true);
    cf.convolve_backward(wf.data(), full_f, half_f, dwf.data(), dbf.data(), dff.data(), dff.cols(),
                         true);
    EXPECT_TRUE(close(dwf, dwd)) << s.height;
    EXPECT_TRUE(close(dff, dfd)) << s.height;
    Vec<double> dcd = Vec<double>::Zero(s.full_channels);
    Vec<float> dcf = Vec<float>::Zero(s.full_channels);
    dwd.setZero();
    dwf.setZero();
    cd.convolve_transposed_backward(w.data(), half, full, dwd.data(), dcd.data(), dhd.data(),
                                    dhd.cols(), true);
    cf.convolve_transposed_backward(wf.data(), half_f, full_f, dwf.data(), dcf.data(), dhf.data(),
                                    dhf.cols(), true);
    EXPECT_TRUE(close(dwf, dwd)) << s.height;
    EXPECT_TRUE(close(dhf, dhd)) << s.height;
  }
}

}  // namespace
}  // namespace corrmp::nn
