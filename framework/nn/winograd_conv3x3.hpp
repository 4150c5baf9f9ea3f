// Winograd convolution F(4x4, 3x3) (Lavin and Gray, "Fast Algorithms for Convolutional Neural
// Networks", 2016) for the stride-1, padding-1, 3x3 layers of the autoencoder (paper, Section
// "Learning the Context": the stride-1 convolutions and their transposed mirrors), which carry
// most of its multiply-adds. It computes the same convolution as im2col + matrix product
// (nn/conv2d.hpp, nn/conv_transpose2d.hpp) with 36 products per 4x4 output tile and channel pair
// instead of 144, the sums being grouped differently: the results agree up to rounding (about
// 1e-6 relative in float on a 32-channel 16x16 layer).
//
// For channels c -> o with 3x3 kernels g_{o,c} (correlation, zero padding 1), an image is cut
// into 4x4 output tiles; tile t reads the 6x6 input patch d_{c,t} whose top-left pixel is one
// up and left of the tile's. With the interpolation points 0, 1, -1, 2, -2 and infinity,
//   B^T = [4 0 -5 0 1 0; 0 -4 -4 1 1 0; 0 4 -4 -1 1 0; 0 -2 -1 2 1 0; 0 2 -1 -2 1 0;
//          0 4 0 -5 0 1],
//   G = [1/4 0 0; -1/6 -1/6 -1/6; -1/6 1/6 -1/6; 1/24 1/12 1/6; 1/24 -1/12 1/6; 0 0 1],
//   A^T = [1 1 1 1 1 0; 0 1 -1 2 -2 0; 0 1 1 4 4 0; 0 1 -1 8 -8 1]
// and, for each of the 36 entries xi of a 6x6 matrix,
//   U_xi[o][c] = (G g_{o,c} G^T)_xi,  V_xi[c][t] = (B^T d_{c,t} B)_xi,  M_xi = U_xi V_xi,
// output tile t of channel o is A^T M_{.,o,t} A + b_o (rows or columns past the image dropped).
// Backward, with dM_{.,o,t} = A dY_{o,t} A^T (dY zero past the image):
//   dU_xi = sum over tiles dM_xi V_xi^T,  dL/dg_{o,c} = G^T dU_{.,o,c} G,
//   dV_xi = U_xi^T dM_xi,  dL/dx = sum over tiles of B dV_{.,c,t} B^T placed at the patches,
// the adjoints of the forward steps. The 36 products run on chunks of whole images (tiles side by
// side, like nn/im2col.hpp's chunks), so each is one matrix product per chunk.
//
// The weight matrix is read in either layer's layout (KernelLayout); a transposed convolution
// with stride 1, padding 1 and no output padding is the convolution with the kernel flipped and
// the channel roles exchanged: g_{o,c}[i][j] = W[c][o][2 - i][2 - j].
#pragma once

#include "nn/buffer.hpp"
#include "nn/tensor.hpp"
#include "nn/thread_scratch.hpp"
#include "nn/weight_stamp.hpp"

namespace corrmp::nn {

enum class KernelLayout {
  kConv,        ///< W is Cout x (Cin 3 3): g_{o,c}[i][j] = W[o][(c 3 + i) 3 + j] (nn/conv2d.hpp)
  kTransposed,  ///< W is Cin x (Cout 3 3), flipped: g_{o,c}[i][j] = W[c][(o 3 + 2 - i) 3 + 2 - j]
};

template <class S>
class WinogradConv3x3 {
 public:
  /// A stride-1, padding-1, 3x3 convolution from in_channels x height x width images to
  /// out_channels x height x width images.
  WinogradConv3x3(Index in_channels, Index out_channels, Index height, Index width,
                  KernelLayout layout);

  /// y = conv(x) + bias, or relu(conv(x) + bias) with relu; x is N x (Cin H W), y is
  /// N x (Cout H W).
  void forward(const S* weight, const S* bias, ConstMatRef<S> x, MatRef<S> y, bool relu = false);

  /// Accumulates dL/dW into weight_grad (the layout of weight) and dL/db into bias_grad, and
  /// overwrites dx (N rows dx_stride apart) with dL/dx unless dx is null. With relu_input, x is
  /// the output of a ReLU and dx is the gradient before it: dL/dx [x > 0].
  void backward(const S* weight, ConstMatRef<S> x, ConstMatRef<S> dy, S* weight_grad, S* bias_grad,
                S* dx, Index dx_stride, bool relu_input = false);

  /// Computes U unless it holds the transform of these very weights, or, with a weight source,
  /// the source does (forward and backward call it first).
  void transform_weights(const S* weight);
  /// For a data-parallel replica: use `source`'s U whenever it is of the same weights. The source
  /// must outlive this layer and not transform other weights while this layer runs (the trainer
  /// transforms its model's weights before the replicas run).
  void share_weight_transforms(const WinogradConv3x3* source) { weight_source_ = source; }

 private:
  static constexpr int kTile = 4;    // output tile side
  static constexpr int kPatch = 6;   // input patch side, kTile + 2
  static constexpr int kTerms = 36;  // entries of a 6x6 patch transform
  // Distance between the term matrices of a chunk (channels x columns each).
  static Index term_stride(Index channels, Index columns);

  // Where the 9 weights of g_{o,c} are in the weight matrix: g_{o,c}[i][j] at offset 3 i + j
  // (KernelLayout::kConv) or 8 - (3 i + j) (kTransposed).
  Index pair_offset(Index o, Index c) const;
  // Images of the batch per chunk.
  Index chunk_images(Index batch) const;
  // Padded row y of a plane laid out as plane_.
  S* plane_row(Vec<S>& plane, Index y) const;
  // V of `count` images (rows `stride` apart) into input_terms() (kTerms matrices Cin x count
  // tiles).
  void transform_inputs(const S* images, Index stride, Index count);
  // dM of `count` output-gradient images into output_terms() (kTerms matrices Cout x count tiles).
  void transform_output_grads(const S* images, Index stride, Index count);
  // Writes A^T M A + b (through a ReLU with relu) from output_terms() into `count` images.
  void write_outputs(const S* bias, Index count, S* images, Index stride, bool relu);
  // Writes the sum of B dV B^T from input_terms() into `count` images, times [input > 0] for the
  // inputs (rows input_stride apart) unless relu_inputs is null.
  void write_input_grads(Index count, S* images, Index stride, const S* relu_inputs,
                         Index input_stride);

  // This thread's scratch (nn/thread_scratch.hpp): V, then dV, of one chunk (kTerms rows,
  // term_stride apart); M or dM of one chunk (likewise); dU summed over the batch.
  static Buffer<S>& input_terms() { return thread_scratch<S>(Scratch::kInputSide); }
  static Buffer<S>& output_terms() { return thread_scratch<S>(Scratch::kOutputSide); }
  static Buffer<S>& weight_grad_terms() { return thread_scratch<S>(Scratch::kGradients); }

  Index in_channels_, out_channels_, height_, width_;
  KernelLayout layout_;
  Index tile_rows_, tile_cols_;  // ceil(H / 4), ceil(W / 4)
  Index column_stride_;          // (tile_rows + 1) tile_cols: one patch column's run, see plane_
  Index block_;                  // 6 column_stride_: one row phase of plane_
  Buffer<S> u_;                  // U (kTerms matrices Cout x Cin, term_stride apart)
  WeightStamp<S> u_stamp_;       // the weights of u_
  const S* u_data_ = nullptr;    // the U in use: u_'s or the weight source's
  const WinogradConv3x3* weight_source_ = nullptr;
  // One channel padded by a zero row on top and a zero column on the left, each row y split into
  // the six patch columns of its tiles (split_patch_columns) and stored by row phase: column q of
  // tile tx of padded row y at (y mod 4) block + (q (tile_rows + 1) + y div 4) tile_cols + tx.
  // So patch row r of every tile is one run, r mod 4 blocks and r div 4 rows of tiles on.
  Vec<S> plane_;
  Vec<S> sums_;          // like plane_: the overlapping patches of the input gradient added up
  Vec<S> rows_;          // B^T applied along the patch rows: 6 blocks like plane_'s
  Vec<S> row_grads_;     // B applied along the patch columns of dV: 6 blocks, zero past the tiles
  Vec<S> tiles_[2];      // the output side's transform stages
  Vec<S> pair_scratch_;  // the weight transforms' stages for one output channel's pairs
};

extern template class WinogradConv3x3<float>;
extern template class WinogradConv3x3<double>;

}  // namespace corrmp::nn
