// Channel-major views of a chunk of images, for the one-product-per-chunk convolutions
// (nn/conv2d.hpp, nn/conv_transpose2d.hpp; column layout in nn/im2col.hpp).
//
// A batch stores image n as row n, C x P values in C, P order (nn/tensor.hpp, P pixels per
// channel). A chunk of `count` images in channel-major order is the C x (count P) row-major
// matrix M with M[c][n P + q] = image n [c][q]: channel c of every image in one row, so a
// product over all of the chunk's pixels is one matrix product.
#pragma once

#include <algorithm>

#include "nn/tensor.hpp"

namespace corrmp::nn {

/// M = the chunk (`count` images, image n at images + n * image_stride) in channel-major
/// order; M holds channels * count * pixels values.
template <class S>
void gather_channel_major(const S* images, Index image_stride, Index count, Index channels,
                          Index pixels, S* M) {
  for (Index n = 0; n < count; ++n)
    for (Index c = 0; c < channels; ++c) {
      const S* src = images + n * image_stride + c * pixels;
      std::copy(src, src + pixels, M + (c * count + n) * pixels);
    }
}

/// The inverse of gather_channel_major: writes every image of the chunk from M.
template <class S>
void scatter_channel_major(const S* M, Index count, Index channels, Index pixels, S* images,
                           Index image_stride) {
  for (Index n = 0; n < count; ++n)
    for (Index c = 0; c < channels; ++c) {
      const S* src = M + (c * count + n) * pixels;
      std::copy(src, src + pixels, images + n * image_stride + c * pixels);
    }
}

/// sums[c] += the sum of channel c (`pixels` values) over every image (row) of `images`: the
/// bias gradient of a convolution, images being dL/dy.
template <class S>
void add_channel_sums(ConstMatRef<S> images, Index channels, Index pixels, S* sums) {
  for (Index n = 0; n < images.rows(); ++n)
    for (Index c = 0; c < channels; ++c)
      sums[c] += ConstMatMap<S>(images.row(n).data() + c * pixels, 1, pixels).sum();
}

}  // namespace corrmp::nn
