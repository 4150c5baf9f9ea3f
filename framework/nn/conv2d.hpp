// 2-D convolution layer (NCHW, square kernel) for the autoencoder encoder of the paper,
// Section "Learning the Context" (kernel 3, strides [2, 1, 2, 1, 2], filters [32..64]).
//
// Shapes: x is N x (Cin H W), y is N x (Cout Ho Wo), each row one image in C, H, W order
// (nn/tensor.hpp). W is Cout x (Cin k k) (PyTorch (Cout, Cin, k, k), row-major), b has Cout
// entries. Per image n, with U = im2col(x_n) (Cin k k x Ho Wo, nn/im2col.hpp):
//   forward:   Y_n = W U + b 1^T                         (Y_n viewed as Cout x Ho Wo)
//   backward:  dL/dW += dY_n U^T                          (accumulated)
//              dL/db += dY_n 1                            (row sums, accumulated)
//              dL/dx_n = col2im(W^T dY_n)                 (overwritten)
// The batch is processed in chunks of positions (nn/im2col.hpp, for_each_position_chunk: several
// whole images, or runs of output rows of one image, sized to keep U in cache): U is the column
// matrix of a chunk and dY its output gradient in channel-major order (nn/channel_major.hpp), so
// each formula above is one matrix product per chunk, summing over all of the chunk's positions
// at once. Y starts as b 1^T and the product is added to it.
// Layers with kernel 3, stride 1 and padding 1 compute the same formulas by Winograd's F(4x4, 3x3)
// (nn/winograd_conv3x3.hpp), with 4 times fewer multiply-adds; those with kernel 3, stride 2,
// padding 1 and at least kMinStride2WinogradChannels channels on both sides by its stride-2
// form (nn/winograd_stride2_conv3x3.hpp), with 1.8 times fewer.
// Initialisation follows torch.nn.Conv2d: W, b ~ U(-1/sqrt(Cin k k), 1/sqrt(Cin k k)), W first.
// The layer's scratch buffers are its thread's (nn/thread_scratch.hpp), sized on first use;
// backward takes the forward input again and recomputes U (cheap next to the products). The
// products run in nn/gemm.hpp. Nothing is allocated once every layer has run on the thread with
// its largest batch, but where Eigen computes the products (double, or float without AVX-512,
// nn/gemm.hpp) those too large for Eigen's 128 KB stack blocking limit (the autoencoder's 32x32
// layers) let Eigen allocate its GEMM workspace: a few allocations per call, negligible next to
// the millions of multiply-adds of such a product.
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

struct Conv2dOptions {
  Index in_channels = 1;
  Index out_channels = 1;
  Index kernel_size = 3;
  Index stride = 1;
  Index padding = 0;
};

template <class S>
class Conv2d {
 public:
  /// A convolution of images of spatial size input_height x input_width.
  Conv2d(const Conv2dOptions& options, Index input_height, Index input_width, Rng& rng);

  /// y = conv(x) + b, or relu(conv(x) + b) with relu (nn/relu_fusion.hpp). x is
  /// N x input_shape().size(), y is N x output_shape().size().
  void forward(ConstMatRef<S> x, MatRef<S> y, bool relu = false);
  /// Accumulates the parameter gradients and writes dx (N x input_shape().size()). With
  /// relu_input, x is the output of a ReLU and dx the gradient before it, dL/dx [x > 0].
  void backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx, bool relu_input = false);
  /// Accumulates dL/dW and dL/db only (for a first layer whose input needs no gradient).
  void accumulate_param_grad(ConstMatRef<S> x, ConstMatRef<S> dy);

  /// Transforms the weights for the layer's fast algorithm (nn/winograd_conv3x3.hpp,
  /// nn/winograd_stride2_conv3x3.hpp) now, if it has one; forward and backward do it when needed.
  void transform_weights();
  /// For a data-parallel replica: use `source`'s transformed weights whenever they are of the
  /// same weights. `source` has this layer's options and sizes, outlives it, and does not
  /// transform other weights while this layer runs.
  void share_weight_transforms(const Conv2d& source);

  /// {prefix + "weight" [Cout, Cin, k, k], prefix + "bias" [Cout]}.
  std::vector<Parameter<S>> parameters(const std::string& prefix = "");

  const Conv2dOptions& options() const { return options_; }
  const ImageShape& input_shape() const { return geometry_.image; }
  ImageShape output_shape() const {
    return {options_.out_channels, geometry_.out_height, geometry_.out_width};
  }
  Index num_parameters() const { return weight_.size() + bias_.size(); }
  ConvAlgorithm algorithm() const {
    return winograd_           ? ConvAlgorithm::kWinograd
           : strided_winograd_ ? ConvAlgorithm::kWinogradStride2
                               : ConvAlgorithm::kIm2col;
  }

  Mat<S>& weight() { return weight_; }  ///< Cout x (Cin k k)
  Vec<S>& bias() { return bias_; }      ///< Cout
  const Mat<S>& weight_grad() const { return weight_grad_; }
  const Vec<S>& bias_grad() const { return bias_grad_; }

 private:
  void check_batch(const char* where, ConstMatRef<S> x, ConstMatRef<S> dy) const;
  // The parameter gradients and, when dx is not null, the input gradient (rows dx_stride apart).
  void backward_chunks(ConstMatRef<S> x, ConstMatRef<S> dy, S* dx, Index dx_stride,
                       bool relu_input);

  Conv2dOptions options_;
  PatchGeometry geometry_;
  Mat<S> weight_;
  Vec<S> bias_;
  Mat<S> weight_grad_;
  Vec<S> bias_grad_;
  std::optional<WinogradConv3x3<S>> winograd_;                 // for kernel 3, stride 1, padding 1
  std::optional<WinogradStride2Conv3x3<S>> strided_winograd_;  // kernel 3, stride 2, padding 1
};

extern template class Conv2d<float>;
extern template class Conv2d<double>;

}  // namespace corrmp::nn
