// 2-D convolution by im2col + matrix product (formulas in nn/conv2d.hpp).
#include "nn/conv2d.hpp"

#include "nn/check.hpp"
#include "nn/im2col.hpp"

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
}

template <class S>
void Conv2d<S>::forward(ConstMatRef<S> x, MatRef<S> y) {
  check_shape("Conv2d::forward", "x", x, x.rows(), input_shape().size());
  check_shape("Conv2d::forward", "y", y, x.rows(), output_shape().size());
  const Index cout = options_.out_channels, positions = geometry_.positions();
  MatMap<S> cols = columns_.resize(geometry_.patch_size(), positions);
  for (Index n = 0; n < x.rows(); ++n) {
    im2col(x.row(n).data(), geometry_, cols.data());
    MatMap<S> y_n(y.row(n).data(), cout, positions);
    y_n.noalias() = weight_ * cols;
    y_n.colwise() += bias_;
  }
}

template <class S>
void Conv2d<S>::check_batch(const char* where, ConstMatRef<S> x, ConstMatRef<S> dy) const {
  check_shape(where, "x", x, x.rows(), input_shape().size());
  check_shape(where, "dy", dy, x.rows(), output_shape().size());
}

template <class S>
void Conv2d<S>::accumulate_param_grad(ConstMatRef<S> x, ConstMatRef<S> dy) {
  check_batch("Conv2d::backward", x, dy);
  const Index cout = options_.out_channels, positions = geometry_.positions();
  MatMap<S> cols = columns_.resize(geometry_.patch_size(), positions);
  for (Index n = 0; n < x.rows(); ++n) {
    im2col(x.row(n).data(), geometry_, cols.data());
    ConstMatMap<S> dy_n(dy.row(n).data(), cout, positions);
    weight_grad_.noalias() += dy_n * cols.transpose();
    bias_grad_.noalias() += dy_n.rowwise().sum();
  }
}

template <class S>
void Conv2d<S>::backward(ConstMatRef<S> x, ConstMatRef<S> dy, MatRef<S> dx) {
  check_shape("Conv2d::backward", "dx", dx, x.rows(), input_shape().size());
  accumulate_param_grad(x, dy);
  const Index cout = options_.out_channels, positions = geometry_.positions();
  MatMap<S> col_grads = column_grads_.resize(geometry_.patch_size(), positions);
  for (Index n = 0; n < x.rows(); ++n) {
    ConstMatMap<S> dy_n(dy.row(n).data(), cout, positions);
    col_grads.noalias() = weight_.transpose() * dy_n;
    col2im(col_grads.data(), geometry_, dx.row(n).data());
  }
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
