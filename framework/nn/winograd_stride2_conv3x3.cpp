// Winograd's algorithm for the stride-2, 3x3 layers (formulas in nn/winograd_stride2_conv3x3.hpp).
//
// Tile t of image n is (tile row ty, tile column tx), row n T + ty TW + tx of the chunk's term
// matrices (T = TH TW tiles per image). Each 2-D transform is two passes of a 1-D transform, each
// a loop over the channels of one tile's pixels or terms (contiguous in the pixel-major planes
// and in the term matrices' rows), so that it vectorises.
#include "nn/winograd_stride2_conv3x3.hpp"

#include <algorithm>
#include <stdexcept>

#include "nn/channel_major.hpp"
#include "nn/gemm.hpp"
#include "nn/pixel_major.hpp"
#include "nn/relu_fusion.hpp"
#include "nn/transpose.hpp"
#include "nn/winograd_stride2_transforms.hpp"

namespace corrmp::nn {

using namespace stride2;  // the 1-D maps

namespace {

// Tiles per chunk (whole images, at least one): the products of a chunk's terms have this many
// rows, and the 81 term matrices of one side of a chunk fit in the core's L2 cache (with 64
// channels, 81 x 64 x 32 floats, 660 KB); chunks of one 4-tile image would leave the products 4
// rows, nn/gemm.hpp's slow remainder case (docs/performance.md, "Measurements behind the code").
constexpr Index kChunkTiles = 32;
// Gap between the 81 term matrices of a chunk: the transforms write (or read) all 81 at the same
// offset, and matrices a power of two apart would fall into the same cache sets.
constexpr Index kTermGap = 16;

}  // namespace

template <class S>
WinogradStride2Conv3x3<S>::WinogradStride2Conv3x3(Index full_channels, Index half_channels,
                                                  Index height, Index width)
    : full_channels_(full_channels),
      half_channels_(half_channels),
      height_(height),
      width_(width),
      half_height_((height + 1) / 2),
      half_width_((width + 1) / 2),
      tile_rows_((half_height_ + 3) / 4),
      tile_cols_((half_width_ + 3) / 4),
      padded_rows_(8 * tile_rows_ + 1),
      padded_cols_(8 * tile_cols_ + 1) {
  if (full_channels < 1 || half_channels < 1 || height < 1 || width < 1)
    throw std::invalid_argument("WinogradStride2Conv3x3: empty shape");
  full_plane_ = Vec<S>::Zero(padded_rows_ * padded_cols_ * full_channels);
  full_sums_ = Vec<S>::Zero(padded_rows_ * padded_cols_ * full_channels);
  half_plane_ = Vec<S>::Zero(16 * tile_rows_ * tile_cols_ * half_channels);
  half_out_ = Vec<S>::Zero(16 * tile_rows_ * tile_cols_ * half_channels);
  stage_ = Vec<S>::Zero(kTerms * std::max(full_channels, half_channels));
}

template <class S>
Index WinogradStride2Conv3x3<S>::term_stride(Index channels, Index count) {
  return channels * count + kTermGap;
}

template <class S>
void WinogradStride2Conv3x3<S>::transform_weights(const S* weight) {
  const Index cin = full_channels_, cout = half_channels_;
  const size_t values = static_cast<size_t>(9 * cin * cout);
  if (u_stamp_.matches(weight, values)) {
    u_data_ = u_.view().data();
    ut_data_ = ut_.view().data();
    return;
  }
  if (weight_source_ != nullptr && weight_source_->u_stamp_.matches(weight, values)) {
    u_data_ = weight_source_->u_data_;
    ut_data_ = weight_source_->ut_data_;
    return;
  }
  const Index stride = term_stride(cout, cin);
  S* u = u_.resize(kWeightTerms, stride).data();
  S* g = stage_.data();   // g_{o,c}[a][b] at g[(3 a + b) cin + c]
  S* rows = g + 9 * cin;  // (G6 g_{o,c})[p][b] at rows[(3 p + b) cin + c]
  for (Index o = 0; o < cout; ++o) {
    for (Index c = 0; c < cin; ++c) {  // the pair's 9 weights are contiguous
      const S* pair = weight + 9 * (o * cin + c);
      for (int e = 0; e < 9; ++e) g[e * cin + c] = pair[e];
    }
    for (int b = 0; b < 3; ++b) weight_6(cin, g + b * cin, 3 * cin, rows + b * cin, 3 * cin);
    for (int p = 0; p < 6; ++p)  // weight term (p, q) row o at u + (6 p + q) stride + o cin
      weight_6(cin, rows + 3 * p * cin, cin, u + 6 * p * stride + o * cin, stride);
  }
  S* ut = ut_.resize(kWeightTerms, stride).data();
  for (int q = 0; q < kWeightTerms; ++q)
    transpose(cout, cin, u + q * stride, cin, ut + q * stride, cout);
  u_data_ = u;
  ut_data_ = ut;
  u_stamp_.set(weight, values);  // last: the terms are complete
}

template <class S>
int WinogradStride2Conv3x3<S>::weight_term(int xi) {
  return 6 * weight_entry(xi / kSide) + weight_entry(xi % kSide);
}

template <class S>
Index WinogradStride2Conv3x3<S>::chunk_images(Index batch) const {
  const Index tiles = tile_rows_ * tile_cols_;
  return std::max<Index>(1, std::min(batch, (kChunkTiles + tiles - 1) / tiles));
}

template <class S>
void WinogradStride2Conv3x3<S>::full_to_terms(const S* images, Index stride, Index count) {
  const Index C = full_channels_, TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(C, columns);
  S* v = input_terms().resize(kTerms, terms).data();
  S* rows = stage_.data();  // the patch's rows transformed: term eta of row u at (9 u + eta) C
  for (Index n = 0; n < count; ++n) {
    // Pixel (h, w) at padded (h + 1, w + 1); the border and the pixels past the image stay zero.
    to_pixel_major(images + n * stride, C, height_, width_,
                   full_plane_.data() + (padded_cols_ + 1) * C, padded_cols_);
    for (Index ty = 0; ty < tile_rows_; ++ty)
      for (Index tx = 0; tx < TW; ++tx) {
        const Index t = n * T + ty * TW + tx;
        for (int u = 0; u < kSide; ++u)  // patch row u is padded row 8 ty + u
          input_9(C, full_plane_.data() + ((8 * ty + u) * padded_cols_ + 8 * tx) * C, C,
                  rows + kSide * u * C, C);
        for (int eta = 0; eta < kSide; ++eta)  // term (xi, eta) at v + (9 xi + eta) terms + t C
          input_9(C, rows + eta * C, kSide * C, v + eta * terms + t * C, kSide * terms);
      }
  }
}

template <class S>
void WinogradStride2Conv3x3<S>::half_to_terms(const S* images, Index stride, Index count) {
  const Index O = half_channels_, TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(O, columns), plane_cols = 4 * TW;
  S* m = output_terms().resize(kTerms, terms).data();
  S* rows = stage_.data();  // the tile's rows expanded: term eta of row i at (9 i + eta) O
  for (Index n = 0; n < count; ++n) {
    to_pixel_major(images + n * stride, O, half_height_, half_width_, half_plane_.data(),
                   plane_cols);
    for (Index ty = 0; ty < tile_rows_; ++ty)
      for (Index tx = 0; tx < TW; ++tx) {
        const Index t = n * T + ty * TW + tx;
        for (int i = 0; i < 4; ++i)
          output_grad_4(O, half_plane_.data() + ((4 * ty + i) * plane_cols + 4 * tx) * O, O,
                        rows + kSide * i * O, O);
        for (int eta = 0; eta < kSide; ++eta)
          output_grad_4(O, rows + eta * O, kSide * O, m + eta * terms + t * O, kSide * terms);
      }
  }
}

template <class S>
void WinogradStride2Conv3x3<S>::terms_to_half(Index count, S* images, Index stride, const S* bias,
                                              bool relu, const S* keep, Index keep_stride) {
  const Index O = half_channels_, TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(O, columns), plane_cols = 4 * TW;
  const S* m = output_terms().view().data();
  S* rows = stage_.data();  // A9^T along eta: value j of term row xi at (4 xi + j) O
  for (Index n = 0; n < count; ++n) {
    for (Index ty = 0; ty < tile_rows_; ++ty)
      for (Index tx = 0; tx < TW; ++tx) {
        const Index t = n * T + ty * TW + tx;
        for (int xi = 0; xi < kSide; ++xi)
          output_9(O, m + kSide * xi * terms + t * O, terms, rows + 4 * xi * O, O);
        for (int j = 0; j < 4; ++j)  // pixel (4 ty + i, 4 tx + j)
          output_9(O, rows + j * O, 4 * O,
                   half_out_.data() + ((4 * ty) * plane_cols + 4 * tx + j) * O, plane_cols * O);
      }
    from_pixel_major(half_out_.data(), plane_cols, O, half_height_, half_width_, bias, relu,
                     images + n * stride);
  }
  if (keep != nullptr) mask_by_relu_output(keep, keep_stride, count, half_size(), images, stride);
}

template <class S>
void WinogradStride2Conv3x3<S>::terms_to_full(Index count, S* images, Index stride, const S* bias,
                                              bool relu, const S* keep, Index keep_stride) {
  const Index C = full_channels_, TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(C, columns);
  const S* v = input_terms().view().data();
  S* rows = stage_.data();  // B9 along eta: patch column col of term row xi at (9 xi + col) C
  for (Index n = 0; n < count; ++n) {
    // Patches overlap by one pixel: tiles in order, each adds its first patch row to what the
    // tile above wrote and its first patch column to what the tile on the left wrote, and writes
    // the rest (the padded border row and column 0 are never read back).
    for (Index ty = 0; ty < tile_rows_; ++ty)
      for (Index tx = 0; tx < TW; ++tx) {
        const Index t = n * T + ty * TW + tx;
        for (int xi = 0; xi < kSide; ++xi)
          input_grad_9<false, false>(C, v + kSide * xi * terms + t * C, terms,
                                     rows + kSide * xi * C, C);
        S* patch = full_sums_.data() + ((8 * ty) * padded_cols_ + 8 * tx) * C;
        const Index step = padded_cols_ * C;
        for (int col = 0; col < kSide; ++col) {
          const S* in = rows + col * C;
          if (col == 0 && tx > 0)
            input_grad_9<true, true>(C, in, kSide * C, patch, step);
          else if (ty > 0)
            input_grad_9<true, false>(C, in, kSide * C, patch + col * C, step);
          else
            input_grad_9<false, false>(C, in, kSide * C, patch + col * C, step);
        }
      }
    from_pixel_major(full_sums_.data() + (padded_cols_ + 1) * C, padded_cols_, C, height_, width_,
                     bias, relu, images + n * stride);
  }
  if (keep != nullptr) mask_by_relu_output(keep, keep_stride, count, full_size(), images, stride);
}

template <class S>
void WinogradStride2Conv3x3<S>::multiply(Buffer<S>& in, Index in_channels, const S* weights,
                                         Buffer<S>& out, Index out_channels, Index columns) {
  const Index in_terms = term_stride(in_channels, columns);
  const Index out_terms = term_stride(out_channels, columns);
  const Index weight_terms = term_stride(in_channels, out_channels);
  out.resize(kTerms, out_terms);
  Buffer<S>& scratch = gemm_scratch<S>();
  for (int xi = 0; xi < kTerms; ++xi)
    gemm<S>(ConstMatMap<S>(in.view().data() + xi * in_terms, columns, in_channels), Op::kPlain,
            ConstMatMap<S>(weights + weight_term(xi) * weight_terms, in_channels, out_channels),
            Op::kPlain, MatMap<S>(out.view().data() + xi * out_terms, columns, out_channels),
            /*accumulate=*/false, scratch);
}

template <class S>
void WinogradStride2Conv3x3<S>::multiply_forward(Index columns) {
  multiply(input_terms(), full_channels_, ut_data_, output_terms(), half_channels_, columns);
}

template <class S>
void WinogradStride2Conv3x3<S>::multiply_adjoint(Index columns) {
  multiply(output_terms(), half_channels_, u_data_, input_terms(), full_channels_, columns);
}

template <class S>
void WinogradStride2Conv3x3<S>::accumulate_weight_terms(Index columns, bool first_chunk) {
  const Index C = full_channels_, O = half_channels_;
  const Index v_terms = term_stride(C, columns), m_terms = term_stride(O, columns);
  const Index u_terms = term_stride(O, C);
  Buffer<S>& dut = weight_grad_terms();
  if (first_chunk) dut.resize(kWeightTerms, u_terms);
  const S* v = input_terms().view().data();
  const S* m = output_terms().view().data();
  Buffer<S>& scratch = gemm_scratch<S>();
  bool written[kWeightTerms] = {};  // in this chunk
  for (int xi = 0; xi < kTerms; ++xi) {
    const int q = weight_term(xi);  // the terms of one weight term add up
    gemm<S>(ConstMatMap<S>(v + xi * v_terms, columns, C), Op::kTransposed,
            ConstMatMap<S>(m + xi * m_terms, columns, O), Op::kPlain,
            MatMap<S>(dut.view().data() + q * u_terms, C, O),
            /*accumulate=*/!first_chunk || written[q], scratch);
    written[q] = true;
  }
}

template <class S>
void WinogradStride2Conv3x3<S>::add_weight_grad(S* weight_grad) {
  const Index cin = full_channels_, cout = half_channels_, stride = term_stride(cout, cin);
  const S* dut = weight_grad_terms().view().data();
  S* rows = stage_.data();      // G6^T along q: (p, b) of channel c at (3 p + b) cout + o
  S* pairs = rows + 18 * cout;  // dL/dg_{o,c}[a][b] at (3 a + b) cout + o
  for (Index c = 0; c < cin; ++c) {
    for (int p = 0; p < 6; ++p)  // dU_{p,q}^T row c at dut + (6 p + q) stride + c cout
      weight_grad_6(cout, dut + 6 * p * stride + c * cout, stride, rows + 3 * p * cout, cout);
    for (int b = 0; b < 3; ++b)
      weight_grad_6(cout, rows + b * cout, 3 * cout, pairs + b * cout, 3 * cout);
    for (Index o = 0; o < cout; ++o) {  // added to the pair's 9 contiguous gradients
      S* pair = weight_grad + 9 * (o * cin + c);
      for (int e = 0; e < 9; ++e) pair[e] += pairs[e * cout + o];
    }
  }
}

template <class S>
void WinogradStride2Conv3x3<S>::convolve(const S* weight, const S* bias, ConstMatRef<S> full,
                                         MatRef<S> half, bool relu) {
  transform_weights(weight);
  const Index batch = full.rows(), chunk = chunk_images(batch), tiles = tile_rows_ * tile_cols_;
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first);
    full_to_terms(full.row(first).data(), full.outerStride(), count);
    multiply_forward(count * tiles);
    terms_to_half(count, half.row(first).data(), half.outerStride(), bias, relu, nullptr, 0);
  }
}

template <class S>
void WinogradStride2Conv3x3<S>::convolve_backward(const S* weight, ConstMatRef<S> full,
                                                  ConstMatRef<S> half_grad, S* weight_grad,
                                                  S* bias_grad, S* full_grad,
                                                  Index full_grad_stride, bool relu_input) {
  const Index batch = full.rows(), chunk = chunk_images(batch), tiles = tile_rows_ * tile_cols_;
  add_channel_sums(half_grad, half_channels_, half_height_ * half_width_, bias_grad);
  if (batch == 0) return;
  transform_weights(weight);
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first);
    full_to_terms(full.row(first).data(), full.outerStride(), count);
    half_to_terms(half_grad.row(first).data(), half_grad.outerStride(), count);
    accumulate_weight_terms(count * tiles, first == 0);
    if (full_grad == nullptr) continue;
    multiply_adjoint(count * tiles);  // V is used up: it takes dV
    terms_to_full(count, full_grad + first * full_grad_stride, full_grad_stride, nullptr, false,
                  relu_input ? full.row(first).data() : nullptr, full.outerStride());
  }
  add_weight_grad(weight_grad);
}

template <class S>
void WinogradStride2Conv3x3<S>::convolve_transposed(const S* weight, const S* bias,
                                                    ConstMatRef<S> half, MatRef<S> full,
                                                    bool relu) {
  transform_weights(weight);
  const Index batch = half.rows(), chunk = chunk_images(batch), tiles = tile_rows_ * tile_cols_;
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first);
    half_to_terms(half.row(first).data(), half.outerStride(), count);
    multiply_adjoint(count * tiles);
    terms_to_full(count, full.row(first).data(), full.outerStride(), bias, relu, nullptr, 0);
  }
}

template <class S>
void WinogradStride2Conv3x3<S>::convolve_transposed_backward(const S* weight, ConstMatRef<S> half,
                                                             ConstMatRef<S> full_grad,
                                                             S* weight_grad, S* bias_grad,
                                                             S* half_grad, Index half_grad_stride,
                                                             bool relu_input) {
  const Index batch = half.rows(), chunk = chunk_images(batch), tiles = tile_rows_ * tile_cols_;
  add_channel_sums(full_grad, full_channels_, height_ * width_, bias_grad);
  if (batch == 0) return;
  transform_weights(weight);
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first);
    full_to_terms(full_grad.row(first).data(), full_grad.outerStride(), count);
    half_to_terms(half.row(first).data(), half.outerStride(), count);
    accumulate_weight_terms(count * tiles, first == 0);
    multiply_forward(count * tiles);  // dM is used up: it takes the product
    terms_to_half(count, half_grad + first * half_grad_stride, half_grad_stride, nullptr, false,
                  relu_input ? half.row(first).data() : nullptr, half.outerStride());
  }
  add_weight_grad(weight_grad);
}

template class WinogradStride2Conv3x3<float>;
template class WinogradStride2Conv3x3<double>;

}  // namespace corrmp::nn
