// Tests of nn/im2col.hpp and nn/conv_geometry.hpp: size formulas, the unfolded layout, and
// col2im being the adjoint of im2col.
#include "nn/im2col.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

TEST(ConvGeometry, OutputSizeFormulas) {
  EXPECT_EQ(conv_output_size(64, 3, 2, 1), 32);
  EXPECT_EQ(conv_output_size(32, 3, 1, 1), 32);
  EXPECT_EQ(conv_output_size(7, 3, 2, 0), 3);
  EXPECT_EQ(conv_output_size(3, 3, 1, 0), 1);
  EXPECT_THROW(conv_output_size(2, 3, 1, 0), std::invalid_argument);
  EXPECT_EQ(conv_transpose_output_size(8, 3, 2, 1, 1), 16);
  EXPECT_EQ(conv_transpose_output_size(8, 3, 2, 1, 0), 15);
  EXPECT_EQ(conv_transpose_output_size(16, 3, 1, 1, 0), 16);
  EXPECT_THROW(conv_transpose_output_size(8, 3, 2, 1, 2), std::invalid_argument);
}

TEST(Im2col, UnfoldsPatchesWithZeroPadding) {
  // One 1x3x3 image with values 1..9, kernel 2, stride 1, padding 1 -> 4x4 positions.
  const PatchGeometry g = conv_patch_geometry({1, 3, 3}, 2, 1, 1);
  ASSERT_EQ(g.patch_size(), 4);
  ASSERT_EQ(g.positions(), 16);
  const double image[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  MatD cols(4, 16);
  im2col(image, g, cols.data());
  // Kernel offset (0, 0) reads X[oh - 1][ow - 1].
  const double expected_row0[16] = {0, 0, 0, 0, 0, 1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 9};
  // Kernel offset (1, 1) reads X[oh][ow].
  const double expected_row3[16] = {1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 9, 0, 0, 0, 0, 0};
  for (Index q = 0; q < 16; ++q) {
    EXPECT_EQ(cols(0, q), expected_row0[q]) << q;
    EXPECT_EQ(cols(3, q), expected_row3[q]) << q;
  }
}

TEST(Im2col, Col2imIsAdjoint) {
  Rng rng(40);
  const Index configs[][4] = {{3, 1, 1, 5}, {3, 2, 1, 6}, {3, 2, 0, 7}, {2, 2, 0, 4}, {4, 3, 2, 5}};
  for (const auto& cfg : configs) {
    const PatchGeometry g = conv_patch_geometry({2, cfg[3], cfg[3] + 1}, cfg[0], cfg[1], cfg[2]);
    const MatD x = testing::random_matrix(1, g.image.size(), rng);
    const MatD y = testing::random_matrix(g.patch_size(), g.positions(), rng);
    MatD ux(g.patch_size(), g.positions()), vy(1, g.image.size());
    im2col(x.data(), g, ux.data());
    col2im(y.data(), g, vy.data());
    const double lhs = (ux.array() * y.array()).sum();
    const double rhs = (x.array() * vy.array()).sum();
    EXPECT_NEAR(lhs, rhs, 1e-12 * (std::abs(lhs) + 1.0));
  }
}

}  // namespace
}  // namespace corrmp::nn
