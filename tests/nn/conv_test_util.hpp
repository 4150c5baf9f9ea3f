// Naive direct-loop convolutions used as references for the im2col-based layers.
#pragma once

#include "nn/conv_geometry.hpp"
#include "nn/tensor.hpp"

namespace corrmp::nn::testing {

/// y[n][o][oh][ow] = b[o] + sum_{c,i,j} w[o][c][i][j] x[n][c][oh s - p + i][ow s - p + j].
/// w is (Cout, Cin, k, k) row-major; x and the result are N x (C H W).
inline Mat<double> naive_conv2d(const Mat<double>& x, const ImageShape& in, const Mat<double>& w,
                                const Vec<double>& b, Index k, Index s, Index p) {
  const Index cout = w.rows();
  const Index ho = conv_output_size(in.height, k, s, p), wo = conv_output_size(in.width, k, s, p);
  Mat<double> y(x.rows(), cout * ho * wo);
  for (Index n = 0; n < x.rows(); ++n)
    for (Index o = 0; o < cout; ++o)
      for (Index oh = 0; oh < ho; ++oh)
        for (Index ow = 0; ow < wo; ++ow) {
          double sum = b[o];
          for (Index c = 0; c < in.channels; ++c)
            for (Index i = 0; i < k; ++i)
              for (Index j = 0; j < k; ++j) {
                const Index h = oh * s - p + i, v = ow * s - p + j;
                if (h < 0 || h >= in.height || v < 0 || v >= in.width) continue;
                sum += w(o, (c * k + i) * k + j) * x(n, (c * in.height + h) * in.width + v);
              }
          y(n, (o * ho + oh) * wo + ow) = sum;
        }
  return y;
}

/// y[n][o][ih s - p + i][iw s - p + j] += w[c][o][i][j] x[n][c][ih][iw], plus b[o] everywhere.
/// w is (Cin, Cout, k, k) row-major; x is N x (Cin H W), the result N x (Cout Ho Wo).
inline Mat<double> naive_conv_transpose2d(const Mat<double>& x, const ImageShape& in,
                                          const Mat<double>& w, const Vec<double>& b, Index k,
                                          Index s, Index p, Index op) {
  const Index cout = b.size();
  const Index ho = conv_transpose_output_size(in.height, k, s, p, op);
  const Index wo = conv_transpose_output_size(in.width, k, s, p, op);
  Mat<double> y(x.rows(), cout * ho * wo);
  for (Index n = 0; n < x.rows(); ++n) {
    for (Index o = 0; o < cout; ++o)
      for (Index q = 0; q < ho * wo; ++q) y(n, o * ho * wo + q) = b[o];
    for (Index c = 0; c < in.channels; ++c)
      for (Index ih = 0; ih < in.height; ++ih)
        for (Index iw = 0; iw < in.width; ++iw)
          for (Index o = 0; o < cout; ++o)
            for (Index i = 0; i < k; ++i)
              for (Index j = 0; j < k; ++j) {
                const Index h = ih * s - p + i, v = iw * s - p + j;
                if (h < 0 || h >= ho || v < 0 || v >= wo) continue;
                y(n, (o * ho + h) * wo + v) +=
                    w(c, (o * k + i) * k + j) * x(n, (c * in.height + ih) * in.width + iw);
              }
  }
  return y;
}

}  // namespace corrmp::nn::testing
