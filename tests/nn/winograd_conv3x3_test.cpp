// Tests of nn/winograd_conv3x3.hpp against direct convolution loops: forward in both kernel
// layouts, the backward formulas (weight, bias and input gradients), odd and tiny image sizes,
// batches cut into several chunks, the fused ReLU (nn/relu_fusion.hpp), and float against double.
#include "nn/winograd_conv3x3.hpp"

#include <gtest/gtest.h>

#include "conv_test_util.hpp"
#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

// dL/dW, dL/db and dL/dx of the stride-1, padding-1, 3x3 convolution y = conv(x) by direct loops,
// for dL/dy = dy; W in the Conv2d layout (Cout, Cin, 3, 3).
struct DirectGrads {
  MatD weight, x;
  Vec<double> bias;
};
DirectGrads direct_backward(const MatD& x, const MatD& dy, const MatD& w, Index cin, Index cout,
                            Index H, Index W) {
  DirectGrads g{MatD::Zero(cout, cin * 9), MatD::Zero(x.rows(), x.cols()), Vec<double>::Zero(cout)};
  for (Index n = 0; n < x.rows(); ++n)
    for (Index o = 0; o < cout; ++o)
      for (Index h = 0; h < H; ++h)
        for (Index v = 0; v < W; ++v) {
          const double d = dy(n, (o * H + h) * W + v);
          g.bias[o] += d;
          for (Index c = 0; c < cin; ++c)
            for (Index i = 0; i < 3; ++i)
              for (Index j = 0; j < 3; ++j) {
                const Index hh = h - 1 + i, vv = v - 1 + j;
                if (hh < 0 || hh >= H || vv < 0 || vv >= W) continue;
                const Index xi = (c * H + hh) * W + vv;
                g.weight(o, c * 9 + i * 3 + j) += d * x(n, xi);
                g.x(n, xi) += d * w(o, c * 9 + i * 3 + j);
              }
        }
  return g;
}

struct Shape {
  Index cin, cout, height, width, batch;
};

const Shape kShapes[] = {
    {3, 4, 5, 6, 2}, {2, 3, 7, 7, 2}, {2, 2, 1, 1, 3},
    {2, 3, 2, 3, 2}, {3, 2, 4, 1, 2}, {64, 8, 16, 16, 5},  // chunks of three images
};

TEST(WinogradConv3x3, ForwardAndBackwardMatchDirectLoops) {
  Rng rng(60);
  for (const Shape& s : kShapes) {
    WinogradConv3x3<double> conv(s.cin, s.cout, s.height, s.width, KernelLayout::kConv);
    const Index in = s.cin * s.height * s.width, out = s.cout * s.height * s.width;
    const MatD w = testing::random_matrix(s.cout, s.cin * 9, rng);
    const Vec<double> b = testing::random_matrix(s.cout, 1, rng);
    const MatD x = testing::random_matrix(s.batch, in, rng);
    MatD y(s.batch, out);
    conv.forward(w.data(), b.data(), x, y);
    const MatD expected = testing::naive_conv2d(x, {s.cin, s.height, s.width}, w, b, 3, 1, 1);
    EXPECT_LE((y - expected).norm(), 1e-12 * expected.norm()) << s.height << "x" << s.width;

    const MatD dy = testing::random_matrix(s.batch, out, rng);
    MatD dw = MatD::Constant(s.cout, s.cin * 9, 0.5), dx(s.batch, in);
    Vec<double> db = Vec<double>::Constant(s.cout, 0.5);  // gradients accumulate
    conv.backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols());
    const DirectGrads g = direct_backward(x, dy, w, s.cin, s.cout, s.height, s.width);
    EXPECT_LE(((dw.array() - 0.5).matrix() - g.weight).norm(), 1e-12 * g.weight.norm());
    EXPECT_LE(((db.array() - 0.5).matrix() - g.bias).norm(), 1e-12 * g.bias.norm());
    EXPECT_LE((dx - g.x).norm(), 1e-12 * g.x.norm());
  }
}

TEST(WinogradConv3x3, TransposedLayoutIsTheStrideOneTransposedConvolution) {
  Rng rng(61);
  for (const Shape& s : kShapes) {
    WinogradConv3x3<double> conv(s.cin, s.cout, s.height, s.width, KernelLayout::kTransposed);
    const MatD w = testing::random_matrix(s.cin, s.cout * 9, rng);  // (Cin, Cout, 3, 3)
    const Vec<double> b = testing::random_matrix(s.cout, 1, rng);
    const MatD x = testing::random_matrix(s.batch, s.cin * s.height * s.width, rng);
    MatD y(s.batch, s.cout * s.height * s.width);
    conv.forward(w.data(), b.data(), x, y);
    const MatD expected =
        testing::naive_conv_transpose2d(x, {s.cin, s.height, s.width}, w, b, 3, 1, 1, 0);
    EXPECT_LE((y - expected).norm(), 1e-12 * expected.norm()) << s.height << "x" << s.width;
  }
}

TEST(WinogradConv3x3, FusedReluOnOutputAndInputGradient) {
  Rng rng(62);
  const Shape s{3, 4, 6, 5, 2};
  WinogradConv3x3<double> conv(s.cin, s.cout, s.height, s.width, KernelLayout::kConv);
  const Index in = s.cin * s.height * s.width, out = s.cout * s.height * s.width;
  const MatD w = testing::random_matrix(s.cout, s.cin * 9, rng);
  const Vec<double> b = testing::random_matrix(s.cout, 1, rng);
  const MatD x = testing::random_matrix(s.batch, in, rng).cwiseMax(0.0);  // a ReLU's output
  MatD y(s.batch, out), y_relu(s.batch, out);
  conv.forward(w.data(), b.data(), x, y);
  conv.forward(w.data(), b.data(), x, y_relu, /*relu=*/true);
  EXPECT_EQ(y_relu, y.cwiseMax(0.0));

  const MatD dy = testing::random_matrix(s.batch, out, rng);
  MatD dw = MatD::Zero(s.cout, s.cin * 9), dx(s.batch, in), dx_masked(s.batch, in);
  Vec<double> db = Vec<double>::Zero(s.cout);
  conv.backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols());
  conv.backward(w.data(), x, dy, dw.data(), db.data(), dx_masked.data(), dx.cols(),
                /*relu_input=*/true);
  EXPECT_EQ(dx_masked, (x.array() > 0.0).select(dx, 0.0));
}

// The layer keeps the transformed weights for the next call with the same weights; weights
// changed in place (the same array, as after an optimiser step) must be transformed again.
TEST(WinogradConv3x3, WeightsChangedInPlaceAreTransformedAgain) {
  Rng rng(65);
  const Shape s{3, 4, 5, 6, 2};
  const Index in = s.cin * s.height * s.width, out = s.cout * s.height * s.width;
  WinogradConv3x3<double> kept(s.cin, s.cout, s.height, s.width, KernelLayout::kConv);
  MatD w = testing::random_matrix(s.cout, s.cin * 9, rng);
  const Vec<double> b = testing::random_matrix(s.cout, 1, rng);
  const MatD x = testing::random_matrix(s.batch, in, rng);
  const MatD dy = testing::random_matrix(s.batch, out, rng);
  MatD y(s.batch, out), dw = MatD::Zero(s.cout, s.cin * 9), dx(s.batch, in);
  Vec<double> db = Vec<double>::Zero(s.cout);
  kept.forward(w.data(), b.data(), x, y);
  kept.backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols());
  w(1, 4) += 0.25;  // one entry
  kept.forward(w.data(), b.data(), x, y);
  EXPECT_LE((y - testing::naive_conv2d(x, {s.cin, s.height, s.width}, w, b, 3, 1, 1)).norm(),
            1e-12 * y.norm());
  w(2, 0) -= 0.5;  // changed between a forward and the backward
  kept.backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols());
  EXPECT_LE((dx - direct_backward(x, dy, w, s.cin, s.cout, s.height, s.width).x).norm(),
            1e-12 * dx.norm());
}

// The first chunk's products write dU in place of adding to it; an empty batch has no chunk.
TEST(WinogradConv3x3, AnEmptyBatchAddsNoGradient) {
  Rng rng(66);
  WinogradConv3x3<double> conv(2, 3, 4, 4, KernelLayout::kConv);
  const MatD w = testing::random_matrix(3, 2 * 9, rng);
  const MatD x = testing::random_matrix(2, 2 * 16, rng),
             dy = testing::random_matrix(2, 3 * 16, rng);
  MatD dw = MatD::Zero(3, 2 * 9), dx(2, 2 * 16);
  Vec<double> db = Vec<double>::Zero(3);
  conv.backward(w.data(), x, dy, dw.data(), db.data(), dx.data(), dx.cols());  // dU not zero now
  const MatD before = dw;
  conv.backward(w.data(), x.topRows(0), dy.topRows(0), dw.data(), db.data(), nullptr, 0);
  EXPECT_EQ(dw, before);
}

TEST(WinogradConv3x3, FloatAgreesWithDouble) {
  Rng rng(63);
  const Shape s{32, 32, 16, 16, 3};
  WinogradConv3x3<double> cd(s.cin, s.cout, s.height, s.width, KernelLayout::kConv);
  WinogradConv3x3<float> cf(s.cin, s.cout, s.height, s.width, KernelLayout::kConv);
  const MatD w = testing::random_matrix(s.cout, s.cin * 9, rng, -0.06, 0.06);
  const Vec<double> b = testing::random_matrix(s.cout, 1, rng, -0.06, 0.06);
  const MatD x = testing::random_matrix(s.batch, s.cin * s.height * s.width, rng, 0.0, 1.0);
  MatD yd(s.batch, s.cout * s.height * s.width);
  Mat<float> yf(s.batch, yd.cols());
  const Mat<float> wf = w.cast<float>(), xf = x.cast<float>();
  const Vec<float> bf = b.cast<float>();
  cd.forward(w.data(), b.data(), x, yd);
  cf.forward(wf.data(), bf.data(), xf, yf);
  EXPECT_LE((yf.cast<double>() - yd).cwiseAbs().maxCoeff(), 1e-5);
}

// The float path (where rows of 16 or 32 pixels are split and merged with SSE, nn/row_phases.hpp)
// against double, forward and backward, with and without the fused ReLUs.
TEST(WinogradConv3x3, FloatForwardAndBackwardAgreeWithDouble) {
  Rng rng(64);
  const Shape shapes[] = {{16, 16, 16, 16, 2}, {8, 8, 32, 32, 2}};
  for (const Shape& s : shapes)
    for (const bool relu : {false, true}) {
      WinogradConv3x3<double> cd(s.cin, s.cout, s.height, s.width, KernelLayout::kConv);
      WinogradConv3x3<float> cf(s.cin, s.cout, s.height, s.width, KernelLayout::kConv);
      const Index in = s.cin * s.height * s.width, out = s.cout * s.height * s.width;
      const MatD w = testing::random_matrix(s.cout, s.cin * 9, rng, -0.1, 0.1);
      const Vec<double> b = testing::random_matrix(s.cout, 1, rng, -0.1, 0.1);
      const MatD x =
          testing::random_matrix(s.batch, in, rng, -1.0, 1.0).cwiseMax(relu ? 0.0 : -1.0);
      const MatD dy = testing::random_matrix(s.batch, out, rng, -1.0, 1.0);
      const Mat<float> wf = w.cast<float>(), xf = x.cast<float>(), dyf = dy.cast<float>();
      const Vec<float> bf = b.cast<float>();
      const auto close = [](const auto& f, const auto& d) {
        return (f.template cast<double>() - d).cwiseAbs().maxCoeff() <=
               1e-5 * d.cwiseAbs().maxCoeff();
      };

      MatD yd(s.batch, out);
      Mat<float> yf(s.batch, out);
      cd.forward(w.data(), b.data(), x, yd, relu);
      cf.forward(wf.data(), bf.data(), xf, yf, relu);
      EXPECT_TRUE(close(yf, yd)) << s.width << " relu " << relu;

      MatD dwd = MatD::Zero(s.cout, s.cin * 9), dxd(s.batch, in);
      Mat<float> dwf = Mat<float>::Zero(s.cout, s.cin * 9), dxf(s.batch, in);
      Vec<double> dbd = Vec<double>::Zero(s.cout);
      Vec<float> dbf = Vec<float>::Zero(s.cout);
      cd.backward(w.data(), x, dy, dwd.data(), dbd.data(), dxd.data(), in, relu);
      cf.backward(wf.data(), xf, dyf, dwf.data(), dbf.data(), dxf.data(), in, relu);
      EXPECT_TRUE(close(dwf, dwd)) << s.width << " relu " << relu;
      EXPECT_TRUE(close(dbf, dbd)) << s.width << " relu " << relu;
      EXPECT_TRUE(close(dxf, dxd)) << s.width << " relu " << relu;
    }
}

}  // namespace
}  // namespace corrmp::nn
