// Patch unfolding (im2col) and folding (col2im), which turn Conv2d and ConvTranspose2d into
// matrix products (nn/conv2d.hpp, nn/conv_transpose2d.hpp).
//
// For a PatchGeometry g over an image X (C x H x W, stored C, H, W order) the column matrix
// `cols` is row-major with g.patch_size() rows and g.positions() columns:
//   cols[(c k + i) k + j][oh Wo + ow] = X[c][oh s - p + i][ow s - p + j]   (0 outside X)
// im2col writes cols from X. col2im is its adjoint: it writes X[c][h][w] = the sum of all
// cols entries that im2col would read from (c, h, w), so <im2col(X), Y> = <X, col2im(Y)>.
//
// The chunked forms unfold a piece of a batch at once, so that a layer needs one matrix product
// per chunk instead of one per image, with a column matrix small enough to stay in the core's
// cache: a PositionChunk holds either several whole images or some output rows of one image.
// With Pc = chunk.positions(g) patch positions per image, the chunk's n-th image (batch image
// chunk.image_begin + n, at images + (chunk.image_begin + n) * image_stride) owns columns
// [n Pc, (n + 1) Pc) of a g.patch_size() x chunk.columns(g) row-major matrix, in the order of
// its positions (output rows chunk.row_begin .. chunk.row_end - 1).
#pragma once

#include <algorithm>

#include "nn/conv_geometry.hpp"

namespace corrmp::nn {

/// Unfolds `image` (g.image.size() values) into `cols` (g.patch_size() * g.positions()).
template <class S>
void im2col(const S* image, const PatchGeometry& g, S* cols);

/// Folds `cols` back into `image`, overwriting it with the adjoint of im2col.
template <class S>
void col2im(const S* cols, const PatchGeometry& g, S* image);

/// Output rows [row_begin, row_end) of the images [image_begin, image_begin + images).
struct PositionChunk {
  Index image_begin = 0;
  Index images = 1;
  Index row_begin = 0;
  Index row_end = 0;

  /// Patch positions of one image in the chunk.
  Index positions(const PatchGeometry& g) const { return (row_end - row_begin) * g.out_width; }
  /// Columns of the chunk's column matrix.
  Index columns(const PatchGeometry& g) const { return images * positions(g); }
  /// Whether the chunk holds its images' every position.
  bool whole_images(const PatchGeometry& g) const {
    return row_begin == 0 && row_end == g.out_height;
  }
};

/// Unfolds the chunk of the batch `images` (image n at images + n * image_stride) into the
/// g.patch_size() x chunk.columns(g) matrix `cols`.
template <class S>
void im2col_chunk(const S* images, Index image_stride, const PatchGeometry& g,
                  const PositionChunk& chunk, S* cols);

/// Adds the adjoint of im2col_chunk of the g.patch_size() x chunk.columns(g) matrix `cols` into
/// the batch `images`. A chunk starting at output row 0 first overwrites its images with
/// channel_bias[c] on channel c (0 when channel_bias is null), so folding the chunks of
/// for_each_position_chunk in order writes bias + col2im of every image.
template <class S>
void col2im_chunk(const S* cols, const PatchGeometry& g, const PositionChunk& chunk, S* images,
                  Index image_stride, const S* channel_bias = nullptr);

/// Column matrices of chunks hold at most about this many values (256 KB of floats), which
/// keeps them and Eigen's packed copies in the core's L2 cache.
inline constexpr Index kChunkColumnValues = Index(1) << 16;

/// Calls f(const PositionChunk&) for consecutive chunks covering images [0, batch): as many
/// whole images per chunk as fit in kChunkColumnValues column values, or, for larger images,
/// equal runs of output rows of one image (at least one row, at least one image).
template <class F>
void for_each_position_chunk(const PatchGeometry& g, Index batch, F&& f) {
  const Index per_row = std::max<Index>(1, g.patch_size() * g.out_width);
  const Index per_image = per_row * g.out_height;
  const auto even_split = [](Index total, Index most) {  // parts of at most `most`, balanced
    const Index parts = (total + most - 1) / most;
    return (total + parts - 1) / parts;
  };
  if (per_image <= kChunkColumnValues) {
    if (batch < 1) return;
    const Index images = even_split(batch, std::max<Index>(1, kChunkColumnValues / per_image));
    for (Index first = 0; first < batch; first += images)
      f(PositionChunk{first, std::min(images, batch - first), 0, g.out_height});
    return;
  }
  const Index rows = even_split(g.out_height, std::max<Index>(1, kChunkColumnValues / per_row));
  for (Index n = 0; n < batch; ++n)
    for (Index row = 0; row < g.out_height; row += rows)
      f(PositionChunk{n, 1, row, std::min(row + rows, g.out_height)});
}

}  // namespace corrmp::nn
