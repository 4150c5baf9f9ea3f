// 2-D transposed convolution by matrix product + col2im (formulas in nn/conv_transpose2d.hpp).
#include "nn/conv_transpose2d.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "nn/check.hpp"
#include "nn/im2col.hpp"

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
}

template <class S>
void ConvTranspose2d<S>::forward(ConstMatRef<S> x, MatRef<S> y) {
  check_shape("ConvTranspose2d::forward", "x", x, x.rows(), input_shape().size());
  check_shape("ConvTranspose2d::forward", "y", y, x.rows(), output_shape().size());
  const Index cin = options_.in_channels, cout = options_.out_channels;
  const Index in_pixels = geometry_.positions();
  const Index out_pixels = output_shape().height * output_shape().width;
  MatMap<S> cols = columns_.resize(geometry_.patch_size(), in_pixels);
  for (Index n = 0; n < x.rows(); ++n) {
    ConstMatMap<S> x_n(x.row(n).data(), cin, in_pixels);
    cols.noalias() = weight_.transpose() * x_n;
    col2im(cols.data(), geometry_, y.row(n).data());
    MatMap<S>(y.row(n).data(), cout, out_pixels).colwise() += bias_;
  }
}

template <class S>
void ConvTranspose2d<S>::backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx) {
  check_shape("ConvTranspose2d::backward", "x", x, x.rows(), input_shape().size());
  check_shape("ConvTranspose2d::backward", "dy", dy, x.rows(), output_shape().size());
  check_shape("ConvTranspose2d::backward", "dx", dx, x.rows(), input_shape().size());
  const Index cin = options_.in_channels, cout = options_.out_channels;
  const Index in_pixels = geometry_.positions();
  const Index out_pixels = output_shape().height * output_shape().width;
  MatMap<S> cols = columns_.resize(geometry_.patch_size(), in_pixels);
  for (Index n = 0; n < x.rows(); ++n) {
    im2col(dy.row(n).data(), geometry_, cols.data());
    ConstMatMap<S> x_n(x.row(n).data(), cin, in_pixels);
    weight_grad_.noalias() += x_n * cols.transpose();
    bias_grad_.noalias() += ConstMatMap<S>(dy.row(n).data(), cout, out_pixels).rowwise().sum();
    MatMap<S>(dx.row(n).data(), cin, in_pixels).noalias() = weight_ * cols;
  }
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
