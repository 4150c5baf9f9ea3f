// 2-D convolution by im2col + matrix product (formulas in nn/conv2d.hpp).
#include "nn/conv2d.hpp"

#include <algorithm>

#include "nn/channel_major.hpp"
#include "nn/check.hpp"
#include "nn/gemm.hpp"
#include "nn/im2col.hpp"
#include "nn/relu_fusion.hpp"
#include "nn/thread_scratch.hpp"

namespace corrmp::nn {

template <class S>
Conv2d<S>::Conv2d(const Conv2dOptions& options, Index input_height, Index input_width, Rng& rng)
    : options_(options),
      geometry_(conv_patch_geometry({options.in_channels, input_height, input_width},
                                    options.kernel_size, options.stride, options.padding)),
      weight_(options.out_channels, geometry_.patch_size()),
      bias_(options.out_channels),
      weight_grad_(Mat<S>::Zero(options.out_channels, geometry_.patch_size())),
      bias_grad_(Vec<S>::Zero(options.out_channels)) {
  const double bound = default_init_bound(geometry_.patch_size());
  fill_uniform(rng, bound, weight_.data(), weight_.size());
  fill_uniform(rng, bound, bias_.data(), bias_.size());
  if (options.kernel_size == 3 && options.stride == 1 && options.padding == 1)
    winograd_.emplace(options.in_channels, options.out_channels, input_height, input_width,
                      KernelLayout::kConv);
  if (options.kernel_size == 3 && options.stride == 2 && options.padding == 1 &&
      std::min(options.in_channels, options.out_channels) >= kMinStride2WinogradChannels)
    strided_winograd_.emplace(options.in_channels, options.out_channels, input_height, input_width);
}

template <class S>
void Conv2d<S>::forward(ConstMatRef<S> x, MatRef<S> y, bool relu) {
  check_shape("Conv2d::forward", "x", x, x.rows(), input_shape().size());
  check_shape("Conv2d::forward", "y", y, x.rows(), output_shape().size());
  if (winograd_) {
    winograd_->forward(weight_.data(), bias_.data(), x, y, relu);
    return;
  }
  if (strided_winograd_) {
    strided_winograd_->convolve(weight_.data(), bias_.data(), x, y, relu);
    return;
  }
  const Index cout = options_.out_channels, positions = geometry_.positions();
  // This thread's scratch (nn/thread_scratch.hpp): a chunk's columns, and its outputs
  // channel-major.
  Buffer<S>& columns_buffer = thread_scratch<S>(Scratch::kInputSide);
  Buffer<S>& outputs_buffer = thread_scratch<S>(Scratch::kOutputSide);
  Buffer<S>& scratch = gemm_scratch<S>();
  for_each_position_chunk(geometry_, x.rows(), [&](const PositionChunk& chunk) {
    const Index columns = chunk.columns(geometry_);
    MatMap<S> cols = columns_buffer.resize(geometry_.patch_size(), columns);
    im2col_chunk(x.data(), x.outerStride(), geometry_, chunk, cols.data());
    S* y_first = y.row(chunk.image_begin).data();
    if (chunk.images == 1) {  // positions of one image: a block of its rows, written in place
      StridedMap<S> out(y_first + chunk.row_begin * geometry_.out_width, cout, columns,
                        Eigen::OuterStride<>(positions));
      out.colwise() = bias_;
      gemm<S>(weight_, Op::kPlain, cols, Op::kPlain, out, /*accumulate=*/true, scratch);
      if (relu) relu_in_place(out);
      return;
    }
    MatMap<S> out = outputs_buffer.resize(cout, columns);
    out.colwise() = bias_;
    gemm<S>(weight_, Op::kPlain, cols, Op::kPlain, out, /*accumulate=*/true, scratch);
    if (relu) relu_in_place(out);
    scatter_channel_major(out.data(), chunk.images, cout, positions, y_first, y.outerStride());
  });
}

template <class S>
void Conv2d<S>::check_batch(const char* where, ConstMatRef<S> x, ConstMatRef<S> dy) const {
  check_shape(where, "x", x, x.rows(), input_shape().size());
  check_shape(where, "dy", dy, x.rows(), output_shape().size());
}

template <class S>
void Conv2d<S>::backward_chunks(ConstMatRef<S> x, ConstMatRef<S> dy, S* dx, Index dx_stride,
                                bool relu_input) {
  if (winograd_) {
    winograd_->backward(weight_.data(), x, dy, weight_grad_.data(), bias_grad_.data(), dx,
                        dx_stride, relu_input);
    return;
  }
  if (strided_winograd_) {
    strided_winograd_->convolve_backward(weight_.data(), x, dy, weight_grad_.data(),
                                         bias_grad_.data(), dx, dx_stride, relu_input);
    return;
  }
  const Index cout = options_.out_channels, positions = geometry_.positions();
  // This thread's scratch (nn/thread_scratch.hpp): a chunk's columns, its output gradients
  // channel-major, and the columns' gradients W^T dY.
  Buffer<S>& columns_buffer = thread_scratch<S>(Scratch::kInputSide);
  Buffer<S>& outputs_buffer = thread_scratch<S>(Scratch::kOutputSide);
  Buffer<S>& column_grads_buffer = thread_scratch<S>(Scratch::kGradients);
  Buffer<S>& scratch = gemm_scratch<S>();
  for_each_position_chunk(geometry_, x.rows(), [&](const PositionChunk& chunk) {
    const Index columns = chunk.columns(geometry_);
    MatMap<S> cols = columns_buffer.resize(geometry_.patch_size(), columns);
    im2col_chunk(x.data(), x.outerStride(), geometry_, chunk, cols.data());
    const S* dy_first = dy.row(chunk.image_begin).data();
    // dY of the chunk, channel-major: a block of one image's rows, or the images gathered.
    const ConstStridedMap<S> dy_chunk =
        chunk.images == 1 ? ConstStridedMap<S>(dy_first + chunk.row_begin * geometry_.out_width,
                                               cout, columns, Eigen::OuterStride<>(positions))
                          : ConstStridedMap<S>(outputs_buffer.resize(cout, columns).data(), cout,
                                               columns, Eigen::OuterStride<>(columns));
    if (chunk.images > 1)
      gather_channel_major(dy_first, dy.outerStride(), chunk.images, cout, positions,
                           outputs_buffer.view().data());
    gemm<S>(dy_chunk, Op::kPlain, cols, Op::kTransposed, weight_grad_, /*accumulate=*/true,
            scratch);
    bias_grad_.noalias() += dy_chunk.rowwise().sum();
    if (dx == nullptr) return;
    MatMap<S> col_grads = column_grads_buffer.resize(geometry_.patch_size(), columns);
    gemm<S>(weight_, Op::kTransposed, dy_chunk, Op::kPlain, col_grads, /*accumulate=*/false,
            scratch);
    col2im_chunk(col_grads.data(), geometry_, chunk, dx, dx_stride);
    if (relu_input && chunk.row_end == geometry_.out_height)  // the chunk's images are complete
      mask_by_relu_output(x.row(chunk.image_begin).data(), x.outerStride(), chunk.images,
                          input_shape().size(), dx + chunk.image_begin * dx_stride, dx_stride);
  });
}

template <class S>
void Conv2d<S>::accumulate_param_grad(ConstMatRef<S> x, ConstMatRef<S> dy) {
  check_batch("Conv2d::backward", x, dy);
  backward_chunks(x, dy, nullptr, 0, false);
}

template <class S>
void Conv2d<S>::backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx, bool relu_input) {
  check_batch("Conv2d::backward", x, dy);
  check_shape("Conv2d::backward", "dx", dx, x.rows(), input_shape().size());
  backward_chunks(x, dy, dx.data(), dx.outerStride(), relu_input);
}

template <class S>
void Conv2d<S>::transform_weights() {
  if (winograd_) winograd_->transform_weights(weight_.data());
  if (strided_winograd_) strided_winograd_->transform_weights(weight_.data());
}

template <class S>
void Conv2d<S>::share_weight_transforms(const Conv2d& source) {
  if (winograd_ && source.winograd_) winograd_->share_weight_transforms(&*source.winograd_);
  if (strided_winograd_ && source.strided_winograd_)
    strided_winograd_->share_weight_transforms(&*source.strided_winograd_);
}

template <class S>
std::vector<Parameter<S>> Conv2d<S>::parameters(const std::string& prefix) {
  const Index k = options_.kernel_size;
  return {{prefix + "weight",
           {options_.out_channels, options_.in_channels, k, k},
           weight_.data(),
           weight_grad_.data()},
          {prefix + "bias", {options_.out_channels}, bias_.data(), bias_grad_.data()}};
}

template class Conv2d<float>;
template class Conv2d<double>;

}  // namespace corrmp::nn
