// 2-D transposed convolution by matrix product + col2im (formulas in nn/conv_transpose2d.hpp).
#include "nn/conv_transpose2d.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "nn/channel_major.hpp"
#include "nn/check.hpp"
#include "nn/gemm.hpp"
#include "nn/im2col.hpp"
#include "nn/relu_fusion.hpp"
#include "nn/thread_scratch.hpp"

namespace corrmp::nn {
namespace {

PatchGeometry output_patch_geometry(const ConvTranspose2dOptions& o, Index height, Index width) {
  const Index k = o.kernel_size, s = o.stride, p = o.padding, op = o.output_padding;
  PatchGeometry g;
  g.image = {o.out_channels, conv_transpose_output_size(height, k, s, p, op),
             conv_transpose_output_size(width, k, s, p, op)};
  g.kernel = k;
  g.stride = s;
  g.padding = p;
  g.out_height = height;
  g.out_width = width;
  // With 0 <= op < s the convolution of the output image has exactly height x width positions.
  const PatchGeometry conv = conv_patch_geometry(g.image, k, s, p);
  if (conv.out_height != height || conv.out_width != width)
    throw std::invalid_argument(
        fmt::format("ConvTranspose2d: inconsistent geometry for {}x{}", height, width));
  return g;
}

}  // namespace

template <class S>
ConvTranspose2d<S>::ConvTranspose2d(const ConvTranspose2dOptions& options, Index input_height,
                                    Index input_width, Rng& rng)
    : options_(options),
      geometry_(output_patch_geometry(options, input_height, input_width)),
      weight_(options.in_channels, geometry_.patch_size()),
      bias_(options.out_channels),
      weight_grad_(Mat<S>::Zero(options.in_channels, geometry_.patch_size())),
      bias_grad_(Vec<S>::Zero(options.out_channels)) {
  if (options.in_channels < 1) throw std::invalid_argument("ConvTranspose2d: in_channels < 1");
  const double bound = default_init_bound(geometry_.patch_size());
  fill_uniform(rng, bound, weight_.data(), weight_.size());
  fill_uniform(rng, bound, bias_.data(), bias_.size());
  if (options.kernel_size == 3 && options.stride == 1 && options.padding == 1 &&
      options.output_padding == 0)
    winograd_.emplace(options.in_channels, options.out_channels, input_height, input_width,
                      KernelLayout::kTransposed);
  // The adjoint of the stride-2 convolution of the output image (its geometry checked above).
  if (options.kernel_size == 3 && options.stride == 2 && options.padding == 1 &&
      std::min(options.in_channels, options.out_channels) >= kMinStride2WinogradChannels)
    strided_winograd_.emplace(options.out_channels, options.in_channels, geometry_.image.height,
                              geometry_.image.width);
}

namespace {

// The chunk's input images (rows images + n * stride), channel-major: a block of one image's
// rows in place, or the images gathered into `buffer`.
template <class S>
ConstStridedMap<S> channel_major_chunk(const PatchGeometry& g, const PositionChunk& chunk,
                                       Index channels, const S* images, Index stride,
                                       Buffer<S>& buffer) {
  const Index columns = chunk.columns(g), positions = g.positions();
  const S* first = images + chunk.image_begin * stride;
  if (chunk.images == 1)
    return ConstStridedMap<S>(first + chunk.row_begin * g.out_width, channels, columns,
                              Eigen::OuterStride<>(positions));
  MatMap<S> gathered = buffer.resize(channels, columns);
  gather_channel_major(first, stride, chunk.images, channels, positions, gathered.data());
  return ConstStridedMap<S>(gathered.data(), channels, columns, Eigen::OuterStride<>(columns));
}

}  // namespace

template <class S>
void ConvTranspose2d<S>::forward(ConstMatRef<S> x, MatRef<S> y, bool relu) {
  check_shape("ConvTranspose2d::forward", "x", x, x.rows(), input_shape().size());
  check_shape("ConvTranspose2d::forward", "y", y, x.rows(), output_shape().size());
  if (winograd_) {
    winograd_->forward(weight_.data(), bias_.data(), x, y, relu);
    return;
  }
  if (strided_winograd_) {
    strided_winograd_->convolve_transposed(weight_.data(), bias_.data(), x, y, relu);
    return;
  }
  const Index cin = options_.in_channels;
  // This thread's scratch (nn/thread_scratch.hpp): a chunk's inputs channel-major, and W^T X.
  Buffer<S>& channel_major_buffer = thread_scratch<S>(Scratch::kInputSide);
  Buffer<S>& columns_buffer = thread_scratch<S>(Scratch::kOutputSide);
  Buffer<S>& scratch = gemm_scratch<S>();
  for_each_position_chunk(geometry_, x.rows(), [&](const PositionChunk& chunk) {
    const ConstStridedMap<S> x_chunk =
        channel_major_chunk(geometry_, chunk, cin, x.data(), x.outerStride(), channel_major_buffer);
    MatMap<S> cols = columns_buffer.resize(geometry_.patch_size(), chunk.columns(geometry_));
    gemm<S>(weight_, Op::kTransposed, x_chunk, Op::kPlain, cols, /*accumulate=*/false, scratch);
    col2im_chunk(cols.data(), geometry_, chunk, y.data(), y.outerStride(), bias_.data());
    if (relu && chunk.row_end == geometry_.out_height)  // the chunk's images are complete
      relu_in_place(y.middleRows(chunk.image_begin, chunk.images));
  });
}

template <class S>
void ConvTranspose2d<S>::backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx,
                                  bool relu_input) {
  check_shape("ConvTranspose2d::backward", "x", x, x.rows(), input_shape().size());
  check_shape("ConvTranspose2d::backward", "dy", dy, x.rows(), output_shape().size());
  check_shape("ConvTranspose2d::backward", "dx", dx, x.rows(), input_shape().size());
  if (winograd_) {
    winograd_->backward(weight_.data(), x, dy, weight_grad_.data(), bias_grad_.data(), dx.data(),
                        dx.outerStride(), relu_input);
    return;
  }
  if (strided_winograd_) {
    strided_winograd_->convolve_transposed_backward(weight_.data(), x, dy, weight_grad_.data(),
                                                    bias_grad_.data(), dx.data(), dx.outerStride(),
                                                    relu_input);
    return;
  }
  const Index cin = options_.in_channels, cout = options_.out_channels;
  const Index in_pixels = geometry_.positions();
  const Index out_pixels = output_shape().height * output_shape().width;
  // This thread's scratch (nn/thread_scratch.hpp): a chunk's inputs channel-major, then their
  // gradients, and im2col(dY).
  Buffer<S>& channel_major_buffer = thread_scratch<S>(Scratch::kInputSide);
  Buffer<S>& columns_buffer = thread_scratch<S>(Scratch::kOutputSide);
  Buffer<S>& scratch = gemm_scratch<S>();
  for_each_position_chunk(geometry_, x.rows(), [&](const PositionChunk& chunk) {
    const Index columns = chunk.columns(geometry_);
    if (chunk.row_begin == 0)
      for (Index n = chunk.image_begin; n < chunk.image_begin + chunk.images; ++n)
        bias_grad_.noalias() += ConstMatMap<S>(dy.row(n).data(), cout, out_pixels).rowwise().sum();
    MatMap<S> cols = columns_buffer.resize(geometry_.patch_size(), columns);
    im2col_chunk(dy.data(), dy.outerStride(), geometry_, chunk, cols.data());
    const ConstStridedMap<S> x_chunk =
        channel_major_chunk(geometry_, chunk, cin, x.data(), x.outerStride(), channel_major_buffer);
    gemm<S>(x_chunk, Op::kPlain, cols, Op::kTransposed, weight_grad_, /*accumulate=*/true, scratch);
    S* dx_first = dx.row(chunk.image_begin).data();
    if (chunk.images == 1) {  // a block of one image's rows, written in place
      StridedMap<S> dx_block(dx_first + chunk.row_begin * geometry_.out_width, cin, columns,
                             Eigen::OuterStride<>(in_pixels));
      gemm<S>(weight_, Op::kPlain, cols, Op::kPlain, dx_block, /*accumulate=*/false, scratch);
      if (relu_input)  // x_chunk is the same block of x
        dx_block = (x_chunk.array() > S(0)).select(dx_block.array(), S(0)).matrix();
      return;
    }
    // The gathered inputs are no longer needed: their buffer takes the input gradients.
    MatMap<S> dx_chunk = channel_major_buffer.resize(cin, columns);
    gemm<S>(weight_, Op::kPlain, cols, Op::kPlain, dx_chunk, /*accumulate=*/false, scratch);
    scatter_channel_major(dx_chunk.data(), chunk.images, cin, in_pixels, dx_first,
                          dx.outerStride());
    if (relu_input)
      mask_by_relu_output(x.row(chunk.image_begin).data(), x.outerStride(), chunk.images,
                          input_shape().size(), dx_first, dx.outerStride());
  });
}

template <class S>
void ConvTranspose2d<S>::transform_weights() {
  if (winograd_) winograd_->transform_weights(weight_.data());
  if (strided_winograd_) strided_winograd_->transform_weights(weight_.data());
}

template <class S>
void ConvTranspose2d<S>::share_weight_transforms(const ConvTranspose2d& source) {
  if (winograd_ && source.winograd_) winograd_->share_weight_transforms(&*source.winograd_);
  if (strided_winograd_ && source.strided_winograd_)
    strided_winograd_->share_weight_transforms(&*source.strided_winograd_);
}

template <class S>
std::vector<Parameter<S>> ConvTranspose2d<S>::parameters(const std::string& prefix) {
  const Index k = options_.kernel_size;
  return {{prefix + "weight",
           {options_.in_channels, options_.out_channels, k, k},
           weight_.data(),
           weight_grad_.data()},
          {prefix + "bias", {options_.out_channels}, bias_.data(), bias_grad_.data()}};
}

template class ConvTranspose2d<float>;
template class ConvTranspose2d<double>;

}  // namespace corrmp::nn
