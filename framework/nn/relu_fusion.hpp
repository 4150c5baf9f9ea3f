// The ReLU of the autoencoder (paper, Section "Learning the Context": every convolution but the
// last is followed by a ReLU) applied inside the convolution layers, on data a layer has just
// written and still holds in cache, instead of in a separate pass over the batch (and by the
// Mlp's threads on their own columns, nn/mlp.hpp)
// (nn/activation.hpp's Relu, whose formulas these repeat):
//   forward:  y = max(y, 0)
//   backward: with x = relu(a) the layer's input, dL/da = dL/dx [x > 0]
#pragma once

#include "nn/tensor.hpp"

namespace corrmp::nn {

/// y = max(y, 0) on a view of the layer's output.
template <class View>
void relu_in_place(View&& y) {
  using S = typename std::decay_t<View>::Scalar;
  y = y.cwiseMax(S(0));
}

/// dx = dx [x > 0] on `count` rows of `size` values (x rows x_stride apart, dx rows dx_stride
/// apart).
template <class S>
void mask_by_relu_output(const S* x, Index x_stride, Index count, Index size, S* dx,
                         Index dx_stride) {
  for (Index n = 0; n < count; ++n) {
    const S* __restrict in = x + n * x_stride;
    S* __restrict out = dx + n * dx_stride;
    for (Index k = 0; k < size; ++k) out[k] = in[k] > S(0) ? out[k] : S(0);
  }
}

}  // namespace corrmp::nn
