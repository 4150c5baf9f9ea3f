// Scratch buffers that the convolution layers share, one set per thread (the autoencoder of
// paper Section III "Learning the Context"; data-parallel training in
// context/autoencoder/data_parallel_trainer.hpp).
//
// A convolution's call fills chunk-sized matrices that are dead once the call returns: the Winograd
// term matrices of nn/winograd_conv3x3.hpp and nn/winograd_stride2_conv3x3.hpp and their summed
// weight-term gradients, the im2col columns of nn/conv2d.hpp and nn/conv_transpose2d.hpp. With one
// set per thread instead of one per layer, a layer writes to the lines the previous layer has just
// used, likely still in the core's L2 cache (docs/performance.md, "Scratch per thread").
//
// Rules for a user: a slot's contents are valid only within one call of one layer (the call
// sizes it with Buffer::resize and expects nothing from an earlier call), and a function using a
// slot calls nothing that uses the same slot while its contents are needed. Threads never share
// a slot, so layers of different models may run on different threads at once.
#pragma once

#include "nn/buffer.hpp"

namespace corrmp::nn {

/// The shared buffers.
enum class Scratch {
  /// The input side of one chunk: Winograd's V (then dV), a convolution's im2col columns, a
  /// transposed convolution's inputs channel-major (then their gradients).
  kInputSide,
  /// The output side: Winograd's M or dM, a convolution's outputs channel-major, a transposed
  /// convolution's columns (W^T X or im2col(dY)).
  kOutputSide,
  /// Winograd's weight-term gradients summed over a batch, a convolution's column gradients W^T dY.
  kGradients,
  /// nn/gemm.hpp's transposed operand, through gemm_scratch (held only during one gemm call).
  kGemmOperand,
  kCount,
};

/// This thread's buffer for `slot`; grown on first use, then reused.
template <class S>
Buffer<S>& thread_scratch(Scratch slot);

extern template Buffer<float>& thread_scratch<float>(Scratch);
extern template Buffer<double>& thread_scratch<double>(Scratch);

}  // namespace corrmp::nn
