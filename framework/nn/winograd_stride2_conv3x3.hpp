// Winograd's algorithm for the stride-2 layers of the autoencoder (paper, Section "Learning the
// Context": the kernel 3, stride 2, padding 1 convolutions and their transposed mirrors), which
// carry most of its multiply-adds once the stride-1 layers run F(4x4, 3x3)
// (nn/winograd_conv3x3.hpp). It computes the same convolution as im2col + matrix product
// (nn/conv2d.hpp, nn/conv_transpose2d.hpp) with 81 products per 4x4 output tile and channel pair
// instead of 144, the sums being grouped differently: the results agree up to rounding.
//
// One dimension first. Output j of a stride-2 correlation with taps w0 w1 w2 reads inputs 2j - 1,
// 2j and 2j + 1: the even inputs with the one tap w1, the odd ones (2j - 1 and 2j + 1) with the
// two taps w0 w2, a stride-1 correlation with 2 taps of the odd phase. Four outputs 4t .. 4t + 3
// read the 9 inputs s_u = x[8t - 1 + u]: the 4 even ones s_1 s_3 s_5 s_7 once each, the 5 odd
// ones e_k = s_2k by Winograd's F(4, 2) with the points 0, 1, -1, 2 and infinity:
//   F(4, 2):  B^T = [2 -1 -2 1 0; 0 2 1 -1 0; 0 -2 3 -1 0; 0 -1 0 1 0; 0 2 -1 -2 1],
//             G = [1/2 0; 1/2 1/2; 1/6 -1/6; 1/6 1/3; 0 1],
//             A^T = [1 1 1 1 0; 0 1 -1 2 0; 0 1 1 4 0; 0 1 -1 8 1].
// So the 9 inputs become 9 terms d = (s_1, s_3, s_5, s_7, B^T e), the taps 9 terms
// (w1, w1, w1, w1, G (w0, w2)), and output j is d_j w1 + (A^T (terms 4..8 multiplied))_j: 9
// products for 4 outputs where the direct sum takes 12. Call the three maps B9^T (9 -> 9), G9
// (3 -> 9) and A9^T (9 -> 4). In two dimensions, for channels c (full resolution, H x W) -> o
// (half resolution, ceil(H/2) x ceil(W/2)) and 3x3 kernels g_{o,c}, output tile t (4x4) reads the
// 9x9 input patch p_{c,t} whose top-left pixel is (8 ty - 1, 8 tx - 1), zero outside the image:
//   U_xi[o][c] = (G9 g_{o,c} G9^T)_xi,  V_xi[c][t] = (B9^T p_{c,t} B9)_xi,  M_xi = U_xi V_xi,
// for the 81 entries xi of a 9x9 matrix, and the tile is A9^T M_{.,o,t} A9 + b_o (pixels past the
// image dropped): 81 products per tile and channel pair against 144.
// Backward, with dM_{.,o,t} = A9 dY_{o,t} A9^T (dY zero past the image): dU_xi = sum over tiles
// dM_xi V_xi^T, dL/dg = G9^T dU G9, dV_xi = U_xi^T dM_xi, and dL/dx is the sum of B9 dV_{.,c,t}
// B9^T placed at the patches (which overlap by one pixel). The transposed convolution of the
// decoder (stride 2, padding 1, output padding 0 or 1) is the adjoint of this convolution with the
// same weights: its forward is the input gradient's path, its input gradient the convolution's.
//
// The weights are in the layout half x full x 3 x 3 (g_{o,c}[i][j] at ((o C + c) 3 + i) 3 + j):
// Conv2d's Cout x (Cin 3 3), and ConvTranspose2d's Cin x (Cout 3 3) alike.
//
// Layout: the transforms run on images turned pixel-major (each pixel's channels contiguous), so
// that every step is one loop over channels that vectorises; the term matrices hold the tiles
// in rows (V_xi^T, tiles x C, and M_xi^T, tiles x O), which the products of nn/gemm.hpp take
// without a transpose.
#pragma once

#include "nn/buffer.hpp"
#include "nn/tensor.hpp"
#include "nn/thread_scratch.hpp"
#include "nn/weight_stamp.hpp"

namespace corrmp::nn {

/// The layers use this algorithm when both sides have at least this many channels. With few
/// channels its products are short (3 terms each for the autoencoder's RGB input) and im2col's
/// (27 terms) run faster (docs/performance.md, "Measurements behind the code").
constexpr Index kMinStride2WinogradChannels = 16;

template <class S>
class WinogradStride2Conv3x3 {
 public:
  /// A kernel 3, stride 2, padding 1 convolution from full_channels x height x width images to
  /// half_channels x ceil(height / 2) x ceil(width / 2) images.
  WinogradStride2Conv3x3(Index full_channels, Index half_channels, Index height, Index width);

  Index full_size() const { return full_channels_ * height_ * width_; }
  Index half_size() const { return half_channels_ * half_height_ * half_width_; }

  /// half = conv(full) + bias (through a ReLU with relu); full is N x full_size(), half is
  /// N x half_size() (nn/conv2d.hpp's forward).
  void convolve(const S* weight, const S* bias, ConstMatRef<S> full, MatRef<S> half, bool relu);
  /// Accumulates dL/dW and dL/db (half_channels entries) of convolve, and overwrites full_grad
  /// (N rows full_grad_stride apart) with dL/dfull unless it is null; with relu_input, full is a
  /// ReLU's output and full_grad is masked by [full > 0].
  void convolve_backward(const S* weight, ConstMatRef<S> full, ConstMatRef<S> half_grad,
                         S* weight_grad, S* bias_grad, S* full_grad, Index full_grad_stride,
                         bool relu_input);
  /// full = conv^T(half) + bias (full_channels entries), through a ReLU with relu: the transposed
  /// convolution (nn/conv_transpose2d.hpp's forward).
  void convolve_transposed(const S* weight, const S* bias, ConstMatRef<S> half, MatRef<S> full,
                           bool relu);
  /// Accumulates dL/dW and dL/db of convolve_transposed, and overwrites half_grad (N rows
  /// half_grad_stride apart) with dL/dhalf; with relu_input, half is a ReLU's output and half_grad
  /// is masked.
  void convolve_transposed_backward(const S* weight, ConstMatRef<S> half, ConstMatRef<S> full_grad,
                                    S* weight_grad, S* bias_grad, S* half_grad,
                                    Index half_grad_stride, bool relu_input);

  /// Computes the weight terms unless they are of these very weights, or, with a weight source,
  /// the source's are (the other methods call it first).
  void transform_weights(const S* weight);
  /// For a data-parallel replica: use `source`'s weight terms whenever they are of the same
  /// weights. The source must outlive this layer and not transform other weights while this
  /// layer runs (the trainer transforms its model's weights before the replicas run).
  void share_weight_transforms(const WinogradStride2Conv3x3* source) { weight_source_ = source; }

 private:
  static constexpr int kSide = 9;    // terms per dimension
  static constexpr int kTerms = 81;  // entries of a 9x9 transform
  // G9 repeats the middle tap in its rows 0-3, so U has 6 x 6 distinct terms: U_xi is weight
  // term weight_term(xi), and dU of a weight term sums the products of its terms.
  static constexpr int kWeightTerms = 36;
  static int weight_term(int xi);

  // Distance between the term matrices of a chunk (count x channels each, or the weight terms'
  // channels x count).
  static Index term_stride(Index channels, Index count);
  // Images of the batch per chunk.
  Index chunk_images(Index batch) const;
  // V^T of `count` full-resolution images (rows `stride` apart) into input_terms().
  void full_to_terms(const S* images, Index stride, Index count);
  // dM^T of `count` half-resolution images into output_terms().
  void half_to_terms(const S* images, Index stride, Index count);
  // A9^T M A9 from output_terms() into `count` half-resolution images, plus bias unless null,
  // through a ReLU with relu, masked by [keep > 0] unless keep is null (rows keep_stride apart).
  void terms_to_half(Index count, S* images, Index stride, const S* bias, bool relu, const S* keep,
                     Index keep_stride);
  // The sum of B9 dV B9^T from input_terms() into `count` full-resolution images, likewise.
  void terms_to_full(Index count, S* images, Index stride, const S* bias, bool relu, const S* keep,
                     Index keep_stride);
  // For every term xi: out_xi (columns x out_channels) = in_xi (columns x in_channels) times
  // weight term weight_term(xi) of `weights` (in_channels x out_channels each).
  void multiply(Buffer<S>& in, Index in_channels, const S* weights, Buffer<S>& out,
                Index out_channels, Index columns);
  // For every term: M^T = V^T U^T (forward) or V^T = M^T U (adjoint), on `columns` tiles.
  void multiply_forward(Index columns);
  void multiply_adjoint(Index columns);
  // dU^T (+)= V dM^T summed over the chunk's tiles, per weight term.
  void accumulate_weight_terms(Index columns, bool first_chunk);
  // dL/dg = G9^T dU G9 added to weight_grad (G6^T on the weight terms).
  void add_weight_grad(S* weight_grad);

  // This thread's scratch (nn/thread_scratch.hpp): V^T (or dV^T) of one chunk, 81 matrices
  // tiles x C; M^T (or dM^T) of one chunk, 81 matrices tiles x O; dU^T per weight term summed
  // over the batch, C x O each.
  static Buffer<S>& input_terms() { return thread_scratch<S>(Scratch::kInputSide); }
  static Buffer<S>& output_terms() { return thread_scratch<S>(Scratch::kOutputSide); }
  static Buffer<S>& weight_grad_terms() { return thread_scratch<S>(Scratch::kGradients); }

  Index full_channels_, half_channels_, height_, width_, half_height_, half_width_;
  Index tile_rows_, tile_cols_;      // ceil(half_height / 4), ceil(half_width / 4)
  Index padded_rows_, padded_cols_;  // 8 tile_rows + 1, 8 tile_cols + 1: the full side padded
  Buffer<S> u_;                      // the weight terms, O x C each
  Buffer<S> ut_;                     // their transposes, C x O each
  WeightStamp<S> u_stamp_;           // the weights of u_ and ut_
  const S* u_data_ = nullptr;        // the weight terms in use: u_'s or the weight source's
  const S* ut_data_ = nullptr;       // likewise, transposed
  const WinogradStride2Conv3x3* weight_source_ = nullptr;
  // One full-resolution image pixel-major with a zero border: pixel (h, w) at
  // ((h + 1) padded_cols + w + 1) C, up to 8 tile_rows + 1 rows and columns.
  Vec<S> full_plane_;
  Vec<S> full_sums_;  // like full_plane_: the overlapping patches of terms_to_full added up
  // One half-resolution image pixel-major, 4 tile_rows x 4 tile_cols pixels (zero past it).
  Vec<S> half_plane_;
  Vec<S> half_out_;  // likewise, the tiles terms_to_half writes
  Vec<S> stage_;     // one tile's terms transformed along one dimension: 81 x max(C, O)
};

extern template class WinogradStride2Conv3x3<float>;
extern template class WinogradStride2Conv3x3<double>;

}  // namespace corrmp::nn
