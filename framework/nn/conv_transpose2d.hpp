// 2-D transposed convolution (NCHW, square kernel) for the autoencoder decoder, which "mimics
// the encoder's operations in reverse" (paper, Section "Learning the Context").
//
// Shapes: x is N x (Cin H W), y is N x (Cout Ho Wo) with Ho = (H - 1) s - 2 p + k + op
// (nn/conv_geometry.hpp). W is Cin x (Cout k k) (PyTorch (Cin, Cout, k, k), row-major), b has
// Cout entries. The layer is the adjoint of a Conv2d from Cout x Ho x Wo to Cin x H x W with the
// same k, s, p: with P the patch geometry of that convolution over the OUTPUT image,
//   forward:   Y_n = col2im_P(W^T X_n) + b 1^T          (X_n viewed as Cin x H W)
//   backward:  V = im2col_P(dY_n)                        (Cout k k x H W)
//              dL/dW += X_n V^T                          (accumulated)
//              dL/db += dY_n 1                           (row sums, accumulated)
//              dL/dX_n = W V                             (overwritten)
// The batch is processed in chunks of input pixels (nn/im2col.hpp, for_each_position_chunk), each
// formula being one matrix product over all of a chunk's pixels, with X and dL/dX in
// channel-major order (nn/channel_major.hpp); col2im starts Y at b 1^T.
// With kernel 3, stride 1, padding 1 (and so no output padding) the layer is the convolution with
// the kernel flipped and the channel roles exchanged, computed by Winograd's F(4x4, 3x3)
// (nn/winograd_conv3x3.hpp). With kernel 3, stride 2, padding 1 and at least
// kMinStride2WinogradChannels channels on both sides it is the adjoint of the stride-2
// convolution with the same weights, computed by nn/winograd_stride2_conv3x3.hpp.
// The layer's scratch buffers are its thread's (nn/thread_scratch.hpp), sized on first use.
// Initialisation follows torch.nn.ConvTranspose2d, whose fan_in is computed from weight
// dimension 1, i.e. fan_in = Cout k k: W, b ~ U(-1/sqrt(Cout k k), 1/sqrt(Cout k k)), W first.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nn/buffer.hpp"
#include "nn/conv_geometry.hpp"
#include "nn/parameter.hpp"
#include "nn/rng.hpp"
#include "nn/tensor.hpp"
#include "nn/winograd_conv3x3.hpp"
#include "nn/winograd_stride2_conv3x3.hpp"

namespace corrmp::nn {

struct ConvTranspose2dOptions {
  Index in_channels = 1;
  Index out_channels = 1;
  Index kernel_size = 3;
  Index stride = 1;
  Index padding = 0;
  Index output_padding = 0;  ///< extra rows/columns at the bottom/right, in [0, stride)
};

template <class S>
class ConvTranspose2d {
 public:
  /// A transposed convolution of images of spatial size input_height x input_width.
  ConvTranspose2d(const ConvTranspose2dOptions& options, Index input_height, Index input_width,
                  Rng& rng);

  /// y = conv_transpose(x) + b, or relu(conv_transpose(x) + b) with relu (nn/relu_fusion.hpp).
  /// x is N x input_shape().size(), y is N x output_shape().size().
  void forward(ConstMatRef<S> x, MatRef<S> y, bool relu = false);
  /// Accumulates the parameter gradients and writes dx (N x input_shape().size()). With
  /// relu_input, x is the output of a ReLU and dx the gradient before it, dL/dx [x > 0].
  void backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx, bool relu_input = false);

  /// Transforms the weights for the layer's fast algorithm (nn/winograd_conv3x3.hpp,
  /// nn/winograd_stride2_conv3x3.hpp) now, if it has one; forward and backward do it when needed.
  void transform_weights();
  /// For a data-parallel replica: use `source`'s transformed weights whenever they are of the
  /// same weights. `source` has this layer's options and sizes, outlives it, and does not
  /// transform other weights while this layer runs.
  void share_weight_transforms(const ConvTranspose2d& source);

  /// {prefix + "weight" [Cin, Cout, k, k], prefix + "bias" [Cout]}.
  std::vector<Parameter<S>> parameters(const std::string& prefix = "");

  const ConvTranspose2dOptions& options() const { return options_; }
  ImageShape input_shape() const {
    return {options_.in_channels, geometry_.out_height, geometry_.out_width};
  }
  const ImageShape& output_shape() const { return geometry_.image; }
  Index num_parameters() const { return weight_.size() + bias_.size(); }
  ConvAlgorithm algorithm() const {
    return winograd_           ? ConvAlgorithm::kWinograd
           : strided_winograd_ ? ConvAlgorithm::kWinogradStride2
                               : ConvAlgorithm::kIm2col;
  }

  Mat<S>& weight() { return weight_; }  ///< Cin x (Cout k k)
  Vec<S>& bias() { return bias_; }      ///< Cout
  const Mat<S>& weight_grad() const { return weight_grad_; }
  const Vec<S>& bias_grad() const { return bias_grad_; }

 private:
  ConvTranspose2dOptions options_;
  PatchGeometry geometry_;  // patches of the output image, one position per input pixel
  Mat<S> weight_;
  Vec<S> bias_;
  Mat<S> weight_grad_;
  Vec<S> bias_grad_;
  std::optional<WinogradConv3x3<S>> winograd_;                 // for kernel 3, stride 1, padding 1
  std::optional<WinogradStride2Conv3x3<S>> strided_winograd_;  // kernel 3, stride 2, padding 1
};

extern template class ConvTranspose2d<float>;
extern template class ConvTranspose2d<double>;

}  // namespace corrmp::nn
