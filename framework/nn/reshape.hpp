// Flatten / Unflatten between the autoencoder's convolution stack and its fully connected
// latent layer (paper, Section "Learning the Context": "the output of the encoder is flattened
// and fed into a fully connected layer").
//
// A batch of images is already stored one flattened image per row (nn/tensor.hpp), so Flatten
// and Unflatten are the identity on memory, forward and backward: pass the same matrix on.
// check_image_batch() verifies the row width at the boundary; image_view() shows one image
// (one row) as a C x (H W) row-major matrix, channel c being row c.
#pragma once

#include "nn/check.hpp"
#include "nn/conv_geometry.hpp"
#include "nn/tensor.hpp"

namespace corrmp::nn {

/// Throws std::invalid_argument unless every row of `batch` is one image of `shape`.
template <class Derived>
void check_image_batch(const char* where, const Eigen::DenseBase<Derived>& batch,
                       const ImageShape& shape) {
  check_shape(where, "image batch", batch, batch.rows(), shape.size());
}

/// The image starting at `row` (shape.size() values) as a C x (H W) matrix.
template <class S>
MatMap<S> image_view(S* row, const ImageShape& shape) {
  return MatMap<S>(row, shape.channels, shape.height * shape.width);
}

/// Read-only version of image_view.
template <class S>
ConstMatMap<S> image_view(const S* row, const ImageShape& shape) {
  return ConstMatMap<S>(row, shape.channels, shape.height * shape.width);
}

}  // namespace corrmp::nn
