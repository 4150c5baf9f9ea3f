// Tests of nn/im2col.hpp and nn/conv_geometry.hpp: size formulas, the unfolded layout, col2im
// being the adjoint of im2col, both against their definitions on every code path (generic,
// stride 1, stride 2, the specialised kernel 3 / stride 2 / padding 1), and the chunked forms
// against per-image unfolding.
#include "nn/im2col.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gradient_check.hpp"

namespace corrmp::nn {
namespace {

using testing::MatD;

// im2col by its definition: cols[(c k + i) k + j][oh Wo + ow] = X[c][oh s - p + i][ow s - p + j].
MatD naive_im2col(const double* x, const PatchGeometry& g) {
  MatD cols = MatD::Zero(g.patch_size(), g.positions());
  const Index k = g.kernel, H = g.image.height, W = g.image.width;
  for (Index c = 0; c < g.image.channels; ++c)
    for (Index i = 0; i < k; ++i)
      for (Index j = 0; j < k; ++j)
        for (Index oh = 0; oh < g.out_height; ++oh)
          for (Index ow = 0; ow < g.out_width; ++ow) {
            const Index h = oh * g.stride - g.padding + i, w = ow * g.stride - g.padding + j;
            if (h >= 0 && h < H && w >= 0 && w < W)
              cols((c * k + i) * k + j, oh * g.out_width + ow) = x[(c * H + h) * W + w];
          }
  return cols;
}

// col2im by its definition: every cols entry added to the pixel im2col reads it from.
MatD naive_col2im(const MatD& cols, const PatchGeometry& g) {
  MatD image = MatD::Zero(1, g.image.size());
  const Index k = g.kernel, H = g.image.height, W = g.image.width;
  for (Index c = 0; c < g.image.channels; ++c)
    for (Index i = 0; i < k; ++i)
      for (Index j = 0; j < k; ++j)
        for (Index oh = 0; oh < g.out_height; ++oh)
          for (Index ow = 0; ow < g.out_width; ++ow) {
            const Index h = oh * g.stride - g.padding + i, w = ow * g.stride - g.padding + j;
            if (h >= 0 && h < H && w >= 0 && w < W)
              image(0, (c * H + h) * W + w) += cols((c * k + i) * k + j, oh * g.out_width + ow);
          }
  return image;
}

// {channels, height, width, kernel, stride, padding}: each code path of im2col.cpp.
const Index kGeometries[][6] = {
    {2, 8, 6, 3, 2, 1},  // kernel 3, stride 2, padding 1 on an even image: specialised
    {2, 7, 6, 3, 2, 1},  // the same on an odd height: generic stride 2
    {2, 5, 6, 3, 1, 1},  // stride 1
    {2, 6, 4, 2, 2, 0},  // stride 2 without padding
    {1, 5, 5, 3, 3, 2},  // any stride
    {3, 4, 5, 1, 1, 0},  // 1x1
};

PatchGeometry geometry(const Index (&c)[6]) {
  return conv_patch_geometry({c[0], c[1], c[2]}, c[3], c[4], c[5]);
}

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

TEST(Im2col, MatchesItsDefinitionOnEveryPath) {
  Rng rng(41);
  for (const auto& cfg : kGeometries) {
    const PatchGeometry g = geometry(cfg);
    const MatD x = testing::random_matrix(1, g.image.size(), rng);
    MatD cols(g.patch_size(), g.positions());
    im2col(x.data(), g, cols.data());
    EXPECT_EQ(cols, naive_im2col(x.data(), g)) << cfg[1] << "x" << cfg[2] << " k" << cfg[3];
    const MatD y = testing::random_matrix(g.patch_size(), g.positions(), rng);
    MatD folded(1, g.image.size());
    col2im(y.data(), g, folded.data());
    const MatD expected = naive_col2im(y, g);
    EXPECT_LE((folded - expected).norm(), 1e-12 * expected.norm())
        << cfg[1] << "x" << cfg[2] << " k" << cfg[3];
  }
}

// Float rows of the kernel 3 / stride 2 / padding 1 path, which x86-64 builds with AVX-512 unfold
// and fold 16 outputs at a time: every row width around the vector's (1 to 40 outputs), values
// that float holds exactly, so the folded sums are exact too.
TEST(Im2col, FloatStrideTwoRowsMatchTheDefinition) {
  Rng rng(43);
  for (Index wo = 1; wo <= 40; ++wo) {
    const PatchGeometry g = conv_patch_geometry({2, 6, 2 * wo}, 3, 2, 1);
    MatD x = testing::random_matrix(1, g.image.size(), rng);
    MatD y = testing::random_matrix(g.patch_size(), g.positions(), rng);
    x = (x * 64.0).array().round() / 64.0;
    y = (y * 64.0).array().round() / 64.0;
    const Mat<float> xf = x.cast<float>(), yf = y.cast<float>();
    Mat<float> cols(g.patch_size(), g.positions()), folded(1, g.image.size());
    im2col(xf.data(), g, cols.data());
    EXPECT_EQ(cols.cast<double>(), naive_im2col(x.data(), g)) << wo;
    col2im(yf.data(), g, folded.data());
    EXPECT_EQ(folded.cast<double>(), naive_col2im(y, g)) << wo;
  }
}

// Batches whose chunks hold several whole images and whose chunks split images into row runs.
TEST(Im2col, ChunksCoverTheBatchAndMatchPerImageUnfolding) {
  Rng rng(42);
  const Index cases[][6] = {
      {2, 4, 4, 3, 2, 1},     // tiny images: several per chunk
      {32, 32, 32, 3, 2, 1},  // specialised kernel 3 / stride 2 in row chunks
      {32, 32, 32, 3, 1, 1},  // stride 1 in row chunks
      {40, 30, 30, 3, 2, 0},  // generic stride 2 in row chunks
  };
  for (const auto& cfg : cases) {
    const PatchGeometry g = geometry(cfg);
    const Index batch = 3, positions = g.positions();
    const MatD x = testing::random_matrix(batch, g.image.size(), rng);
    std::vector<MatD> expected_cols, grads;
    for (Index n = 0; n < batch; ++n) {
      expected_cols.push_back(naive_im2col(x.row(n).data(), g));
      grads.push_back(testing::random_matrix(g.patch_size(), positions, rng));
    }
    std::set<std::pair<Index, Index>> covered;  // (image, output row)
    bool several_images = false, row_runs = false;
    const Vec<double> bias = Vec<double>::LinSpaced(g.image.channels, -1.0, 1.0);
    MatD folded(batch, g.image.size());
    for_each_position_chunk(g, batch, [&](const PositionChunk& chunk) {
      several_images |= chunk.images > 1;
      row_runs |= !chunk.whole_images(g);
      const Index per_image = chunk.positions(g), first = chunk.row_begin * g.out_width;
      MatD cols(g.patch_size(), chunk.columns(g));
      im2col_chunk(x.data(), x.cols(), g, chunk, cols.data());
      MatD chunk_grads(g.patch_size(), chunk.columns(g));
      for (Index n = 0; n < chunk.images; ++n) {
        const Index image = chunk.image_begin + n;
        for (Index row = chunk.row_begin; row < chunk.row_end; ++row)
          EXPECT_TRUE(covered.insert({image, row}).second);
        EXPECT_EQ(cols.middleCols(n * per_image, per_image),
                  expected_cols[image].middleCols(first, per_image));
        chunk_grads.middleCols(n * per_image, per_image) =
            grads[image].middleCols(first, per_image);
      }
      col2im_chunk(chunk_grads.data(), g, chunk, folded.data(), folded.cols(), bias.data());
    });
    EXPECT_EQ(covered.size(), static_cast<size_t>(batch * g.out_height));
    EXPECT_TRUE(several_images || row_runs);
    for (Index n = 0; n < batch; ++n) {
      MatD expected = naive_col2im(grads[n], g);
      for (Index c = 0; c < g.image.channels; ++c)
        expected.middleCols(c * g.image.height * g.image.width, g.image.height * g.image.width)
            .array() += bias[c];
      EXPECT_LE((folded.row(n) - expected).norm(), 1e-12 * expected.norm()) << n;
    }
  }
}

TEST(Im2col, ChunkSizes) {
  // Small images share a chunk; large ones are cut into runs of rows within the budget.
  const PatchGeometry small = conv_patch_geometry({2, 4, 4}, 3, 2, 1);
  Index chunks = 0;
  for_each_position_chunk(small, 7, [&](const PositionChunk& c) {
    ++chunks;
    EXPECT_EQ(c.images, 7);
  });
  EXPECT_EQ(chunks, 1);
  const PatchGeometry large = conv_patch_geometry({32, 32, 32}, 3, 1, 1);
  for_each_position_chunk(large, 2, [&](const PositionChunk& c) {
    EXPECT_EQ(c.images, 1);
    EXPECT_LE(large.patch_size() * c.columns(large), kChunkColumnValues);
  });
}

}  // namespace
}  // namespace corrmp::nn
