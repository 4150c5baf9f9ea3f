// Convolution size arithmetic (formulas in nn/conv_geometry.hpp).
#include "nn/conv_geometry.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace corrmp::nn {

Index conv_output_size(Index in, Index kernel, Index stride, Index padding) {
  if (in < 1 || kernel < 1 || stride < 1 || padding < 0)
    throw std::invalid_argument(fmt::format(
        "conv: invalid size {} / kernel {} / stride {} / padding {}", in, kernel, stride, padding));
  const Index span = in + 2 * padding - kernel;
  if (span < 0)
    throw std::invalid_argument(fmt::format(
        "conv: kernel {} does not fit input size {} with padding {}", kernel, in, padding));
  return span / stride + 1;
}

Index conv_transpose_output_size(Index in, Index kernel, Index stride, Index padding,
                                 Index output_padding) {
  if (in < 1 || kernel < 1 || stride < 1 || padding < 0)
    throw std::invalid_argument(
        fmt::format("conv_transpose: invalid size {} / kernel {} / stride {} / padding {}", in,
                    kernel, stride, padding));
  if (output_padding < 0 || output_padding >= stride)
    throw std::invalid_argument(fmt::format(
        "conv_transpose: output_padding {} must be in [0, stride {})", output_padding, stride));
  const Index out = (in - 1) * stride - 2 * padding + kernel + output_padding;
  if (out < 1)
    throw std::invalid_argument(
        fmt::format("conv_transpose: output size {} < 1 for input size {}", out, in));
  return out;
}

PatchGeometry conv_patch_geometry(const ImageShape& image, Index kernel, Index stride,
                                  Index padding) {
  PatchGeometry g;
  g.image = image;
  g.kernel = kernel;
  g.stride = stride;
  g.padding = padding;
  g.out_height = conv_output_size(image.height, kernel, stride, padding);
  g.out_width = conv_output_size(image.width, kernel, stride, padding);
  return g;
}

}  // namespace corrmp::nn
