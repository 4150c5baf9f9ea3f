// Channel-major images (channel c's rows x cols pixels at image + c rows cols, nn/tensor.hpp) to
// and from pixel-major planes (the channels of pixel (h, w) contiguous at
// plane + (h plane_cols + w) channels, plane_cols >= cols), by nn/transpose.hpp: the layout in
// which nn/winograd_stride2_conv3x3.hpp transforms.
#pragma once

#include <algorithm>

#include "nn/tensor.hpp"
#include "nn/transpose.hpp"

namespace corrmp::nn {

template <class S>
void to_pixel_major(const S* image, Index channels, Index rows, Index cols, S* plane,
                    Index plane_cols) {
  for (Index h = 0; h < rows; ++h)
    transpose(channels, cols, image + h * cols, rows * cols, plane + h * plane_cols * channels,
              channels);
}

/// The inverse, plus bias[c] unless bias is null, through a ReLU with relu.
template <class S>
void from_pixel_major(const S* plane, Index plane_cols, Index channels, Index rows, Index cols,
                      const S* bias, bool relu, S* image) {
  const Index pixels = rows * cols;
  for (Index h = 0; h < rows; ++h)
    transpose(cols, channels, plane + h * plane_cols * channels, channels, image + h * cols,
              pixels);
  if (bias == nullptr && !relu) return;
  for (Index c = 0; c < channels; ++c) {
    const S b = bias == nullptr ? S(0) : bias[c];
    S* __restrict out = image + c * pixels;
    if (relu)
      for (Index i = 0; i < pixels; ++i) out[i] = std::max(out[i] + b, S(0));
    else
      for (Index i = 0; i < pixels; ++i) out[i] += b;
  }
}

}  // namespace corrmp::nn
