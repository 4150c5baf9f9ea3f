// Image shapes and convolution size arithmetic for the autoencoder layers (paper, Section
// "Learning the Context": 5 conv layers, kernel 3, strides [2, 1, 2, 1, 2], filters
// [32, 32, 64, 64, 64], and a decoder mirroring them with transposed convolutions).
//
// Sizes along one spatial axis (square kernel, equal stride and padding on both axes):
//   Conv2d:           out = floor((in + 2 p - k) / s) + 1
//   ConvTranspose2d:  out = (in - 1) s - 2 p + k + output_padding,   0 <= output_padding < s
#pragma once

#include "nn/tensor.hpp"

namespace corrmp::nn {

/// The C x H x W shape of one image; a batch row holds size() values in C, H, W order.
struct ImageShape {
  Index channels = 0;
  Index height = 0;
  Index width = 0;

  Index size() const { return channels * height * width; }
  bool operator==(const ImageShape& o) const {
    return channels == o.channels && height == o.height && width == o.width;
  }
  bool operator!=(const ImageShape& o) const { return !(*this == o); }
};

/// How an image is cut into k x k patches: the image (channels, height, width), the patch
/// kernel, stride and zero padding, and the grid of patch positions (out_height x out_width).
/// Conv2d unfolds its input with it; ConvTranspose2d folds into its output with it.
struct PatchGeometry {
  ImageShape image;
  Index kernel = 1;
  Index stride = 1;
  Index padding = 0;
  Index out_height = 0;
  Index out_width = 0;

  /// Rows of the column matrix: one per (channel, kernel row, kernel column).
  Index patch_size() const { return image.channels * kernel * kernel; }
  /// Columns of the column matrix: one per patch position.
  Index positions() const { return out_height * out_width; }
};

/// floor((in + 2 padding - kernel) / stride) + 1; throws std::invalid_argument if not >= 1.
Index conv_output_size(Index in, Index kernel, Index stride, Index padding);

/// (in - 1) stride - 2 padding + kernel + output_padding; throws std::invalid_argument if the
/// result is < 1 or output_padding is not in [0, stride).
Index conv_transpose_output_size(Index in, Index kernel, Index stride, Index padding,
                                 Index output_padding);

/// The patch geometry of a convolution over `image`, with output grid from conv_output_size.
PatchGeometry conv_patch_geometry(const ImageShape& image, Index kernel, Index stride,
                                  Index padding);

/// How a convolution layer computes (nn/conv2d.hpp, nn/conv_transpose2d.hpp): im2col and matrix
/// products, Winograd's F(4x4, 3x3) (nn/winograd_conv3x3.hpp) or its stride-2 form
/// (nn/winograd_stride2_conv3x3.hpp).
enum class ConvAlgorithm { kIm2col, kWinograd, kWinogradStride2 };

}  // namespace corrmp::nn
